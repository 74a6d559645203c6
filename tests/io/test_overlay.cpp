// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <array>

#include <cmath>
#include <limits>

#include "io/overlay.hpp"

using rays::GreyImage;
using rays::Point;
using rays::io::Rgb;
using rays::io::RgbCanvas;

namespace {

constexpr Rgb kRed{255, 0, 0};

GreyImage gradient() {
    GreyImage img;
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) img.at(x, y) = static_cast<std::uint8_t>(x + y);
    return img;
}

bool is_red(const RgbCanvas& c, int x, int y) {
    const std::size_t i = (static_cast<std::size_t>(y) * c.width() + x) * 3;
    return c.rgb()[i] == 255 && c.rgb()[i + 1] == 0 && c.rgb()[i + 2] == 0;
}

int red_count(const RgbCanvas& c) {
    int n = 0;
    for (int y = 0; y < c.height(); ++y)
        for (int x = 0; x < c.width(); ++x) n += is_red(c, x, y);
    return n;
}

}  // namespace

TEST_CASE("the canvas is the frame enlarged by zoom, grey in all three channels") {
    const GreyImage img = gradient();
    const RgbCanvas canvas(img, 3);
    REQUIRE(canvas.width() == 384);
    REQUIRE(canvas.height() == 384);
    REQUIRE(canvas.rgb().size() == 384u * 384u * 3u);
    for (int y = 0; y < 384; y += 7)
        for (int x = 0; x < 384; x += 5) {
            const std::size_t i = (static_cast<std::size_t>(y) * 384 + x) * 3;
            REQUIRE(canvas.rgb()[i] == img.at(x / 3, y / 3));
            REQUIRE(canvas.rgb()[i + 1] == img.at(x / 3, y / 3));
            REQUIRE(canvas.rgb()[i + 2] == img.at(x / 3, y / 3));
        }
    CHECK(RgbCanvas(img, 0).width() == 128);
}

TEST_CASE("a dot fills the zoomed block of its pixel") {
    RgbCanvas canvas(GreyImage{}, 4);
    canvas.dot(Point{3, 5}, kRed);
    CHECK(red_count(canvas) == 16);
    for (int y = 20; y < 24; ++y)
        for (int x = 12; x < 16; ++x) CHECK(is_red(canvas, x, y));
    canvas.dot(Point{-10, 5}, kRed);  // off the canvas: nothing
    CHECK(red_count(canvas) == 16);
}

TEST_CASE("a line joins the centres of its end pixels") {
    RgbCanvas canvas(GreyImage{}, 3);
    canvas.line(Point{1, 1}, Point{5, 1}, kRed);  // canvas row 4, columns 4..16
    CHECK(red_count(canvas) == 13);
    CHECK(is_red(canvas, 4, 4));
    CHECK(is_red(canvas, 16, 4));
    CHECK_FALSE(is_red(canvas, 17, 4));

    RgbCanvas diagonal(GreyImage{}, 1);
    diagonal.line(Point{10, 10}, Point{20, 20}, kRed);
    CHECK(red_count(diagonal) == 11);
    for (int k = 10; k <= 20; ++k) CHECK(is_red(diagonal, k, k));
}

TEST_CASE("lines are clipped to the canvas, far or invalid points are harmless") {
    RgbCanvas canvas(GreyImage{}, 2);
    canvas.line(Point{-1e9, 64}, Point{1e9, 64}, kRed);
    CHECK(red_count(canvas) == 256);
    for (int x = 0; x < 256; ++x) CHECK(is_red(canvas, x, 129));

    RgbCanvas outside(GreyImage{}, 2);
    outside.line(Point{-50, -5}, Point{300, -5}, kRed);
    outside.line(Point{std::nan(""), 3}, Point{4, 4}, kRed);
    outside.line(Point{0, 0}, Point{std::numeric_limits<double>::infinity(), 4}, kRed);
    outside.cross(Point{std::nan(""), 3}, 5, kRed);
    CHECK(red_count(outside) == 0);

    RgbCanvas corner(GreyImage{}, 1);
    corner.line(Point{-10, -10}, Point{10, 10}, kRed);  // enters at the top-left corner
    CHECK(is_red(corner, 0, 0));
    CHECK(is_red(corner, 10, 10));
    CHECK(red_count(corner) == 11);
}

TEST_CASE("a polygon is closed and a cross has two arms") {
    RgbCanvas canvas(GreyImage{}, 1);
    canvas.polygon({Point{10, 10}, Point{20, 10}, Point{20, 20}}, kRed);
    CHECK(is_red(canvas, 15, 10));
    CHECK(is_red(canvas, 20, 15));
    CHECK(is_red(canvas, 15, 15));  // on the closing edge from (20,20) back to (10,10)
    CHECK_FALSE(is_red(canvas, 12, 18));

    RgbCanvas marked(GreyImage{}, 2);
    marked.cross(Point{10, 10}, 3, kRed);  // centre at canvas pixel (20.5 → 21, 21)
    CHECK(red_count(marked) == 13);
    CHECK(is_red(marked, 18, 21));
    CHECK(is_red(marked, 24, 21));
    CHECK(is_red(marked, 21, 18));
    CHECK(is_red(marked, 21, 24));
}

TEST_CASE("set_image repaints the frame and removes the drawing") {
    RgbCanvas canvas(GreyImage{}, 2);
    canvas.line(Point{0, 0}, Point{127, 127}, kRed);
    REQUIRE(red_count(canvas) > 0);
    const GreyImage img = gradient();
    canvas.set_image(img);
    CHECK(red_count(canvas) == 0);
    CHECK(canvas.rgb()[(static_cast<std::size_t>(9) * 256 + 7) * 3] == img.at(3, 4));
}

TEST_CASE("with chroma the canvas is in colour: full-range BT.601, each chroma pixel over its 2x2 block") {
    rays::GreyImage grey;
    grey.px.fill(76);  // red's luma
    rays::Chroma chroma;
    chroma.u.fill(85);
    chroma.v.fill(255);
    chroma.u[0] = chroma.v[0] = 128;  // processing pixels (0..1, 0..1): grey
    chroma.present = true;
    const rays::io::RgbCanvas canvas(grey, chroma, 1);
    const auto px = [&](int x, int y) {
        const std::size_t i = (static_cast<std::size_t>(y) * 128 + static_cast<std::size_t>(x)) * 3;
        return std::array<int, 3>{canvas.rgb()[i], canvas.rgb()[i + 1], canvas.rgb()[i + 2]};
    };
    CHECK(px(1, 1) == std::array<int, 3>{76, 76, 76});
    const auto red = px(2, 0);
    CHECK(red[0] >= 250);
    CHECK(red[1] <= 5);
    CHECK(red[2] <= 5);
    chroma.present = false;  // a mono source: grey
    CHECK(rays::io::RgbCanvas(grey, chroma, 1).rgb()[6] == 76);
}

