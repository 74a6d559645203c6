// SPDX-License-Identifier: Apache-2.0
// Shapes drawn on a Canvas: anti-aliased coverage, mask and truth, occluders, lighting, blur.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "scenes/render.hpp"

using namespace rays;
using namespace rays::scenes;

namespace {

template <class Shape>
SceneFrame draw_alone(const Shape& shape) {
    Canvas canvas;
    canvas.fill(40);
    canvas.paint(shape, 200, true);
    SceneFrame out;
    canvas.finish(out);
    return out;
}

int mask_count(const GreyImage& mask) {
    int n = 0;
    for (auto v : mask.px) n += v == 255;
    return n;
}

}  // namespace

TEST_CASE("A rendered disc has area pi r^2 within 3% and its centre as centroid", "[scenes]") {
    for (const double r : {6.0, 11.5, 20.0})
        for (const double cx : {40.0, 63.3, 80.75}) {
            const SceneFrame f = draw_alone(Disc{cx, 57.6, r});
            CHECK(f.truth.area == Approx(std::numbers::pi * r * r).epsilon(0.03));
            CHECK(f.truth.area == mask_count(f.mask));
            CHECK(f.truth.cx == Approx(cx).margin(0.15));
            CHECK(f.truth.cy == Approx(57.6).margin(0.15));
        }
}

TEST_CASE("Edges are anti-aliased: a half-covered pixel gets the mean grey", "[scenes]") {
    const SceneFrame f = draw_alone(Box{20.0, 20.0, 40.0, 41.0});  // row 41: two of its four sample rows inside
    CHECK(f.image.at(30, 40) == 200);
    CHECK(f.image.at(30, 41) == 120);  // (40 + 200) / 2
    CHECK(f.mask.at(30, 41) == 255);   // coverage 0.5 counts as target
    CHECK(f.image.at(30, 42) == 40);
    CHECK(f.mask.at(30, 42) == 0);
}

TEST_CASE("The star is concave: notches between its points are outside", "[scenes]") {
    const Star star{64, 64, 22, 10, 5, 0.3};
    const SceneFrame f = draw_alone(star);
    CHECK(f.mask.at(64, 64) == 255);
    const double tip = 0.3, notch = 0.3 + std::numbers::pi / 5;
    CHECK(f.mask.at(static_cast<int>(std::lround(64 + 19 * std::cos(tip))), static_cast<int>(std::lround(64 + 19 * std::sin(tip)))) == 255);
    CHECK(f.mask.at(static_cast<int>(std::lround(64 + 14 * std::cos(notch))), static_cast<int>(std::lround(64 + 14 * std::sin(notch)))) == 0);
    CHECK(f.truth.area > std::numbers::pi * 10 * 10);
    CHECK(f.truth.area < 0.75 * std::numbers::pi * 22 * 22);
}

TEST_CASE("The walker is about its height tall and swings its legs with the phase", "[scenes]") {
    const SceneFrame together = draw_alone(Walker{64, 64, 50, 0});
    const SceneFrame apart = draw_alone(Walker{64, 64, 50, std::numbers::pi / 2});
    int top = kFrameSize, bottom = -1;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            if (together.mask.at(x, y)) {
                top = std::min(top, y);
                bottom = std::max(bottom, y);
            }
    CHECK(bottom - top + 1 == Approx(51).margin(3));
    // Across the row just above the feet: one leg's width when together, both legs when swung apart.
    auto width_at = [](const SceneFrame& f, int y) {
        int left = kFrameSize, right = -1;
        for (int x = 0; x < kFrameSize; ++x)
            if (f.mask.at(x, y)) left = std::min(left, x), right = std::max(right, x);
        return right - left + 1;
    };
    CHECK(width_at(together, 86) < 8);
    CHECK(width_at(apart, 86) > 16);
}

TEST_CASE("An occluder hides the target in the mask and the image", "[scenes]") {
    Canvas canvas;
    canvas.fill(40);
    canvas.paint(Ellipse{64, 64, 14, 10}, 200, true);
    SceneFrame whole;
    canvas.finish(whole);
    canvas.occlude(60, -1, 68, 128, 20);  // covers columns 61–67 fully, 60 and 68 by half
    SceneFrame hidden;
    canvas.finish(hidden);
    int behind_bar = 0;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 61; x <= 67; ++x) {
            behind_bar += whole.mask.at(x, y) == 255;
            CHECK(hidden.mask.at(x, y) == 0);
            CHECK(hidden.image.at(x, y) == 20);
        }
    CHECK(behind_bar > 100);
    CHECK(hidden.truth.area == whole.truth.area - behind_bar);
    CHECK(hidden.mask.at(52, 64) == 255);
}

TEST_CASE("A shadow darkens background and target alike", "[scenes]") {
    Canvas canvas;
    canvas.fill(100);
    canvas.paint(Disc{64, 64, 10}, 200, true);
    SceneFrame sunlit;
    canvas.finish(sunlit);
    canvas.multiply_half_plane(1, 0, 64, 0.5);  // shadow where x > 64
    SceneFrame f;
    canvas.finish(f);
    CHECK(f.image.at(58, 64) == 200);
    CHECK(f.image.at(70, 64) == 100);
    CHECK(f.image.at(20, 20) == 100);
    CHECK(f.image.at(100, 20) == 50);
    CHECK(f.mask.px == sunlit.mask.px);  // lighting leaves the truth alone
}

TEST_CASE("A gradient background rises by its slope per pixel from its centre value", "[scenes]") {
    Canvas canvas;
    canvas.gradient(100, 0.5, -0.25);  // centre of the frame at (63.5, 63.5)
    SceneFrame f;
    canvas.finish(f);
    CHECK(f.image.at(0, 0) == std::lround(100 - 0.5 * 63.5 + 0.25 * 63.5));
    CHECK(f.image.at(127, 0) == std::lround(100 + 0.5 * 63.5 + 0.25 * 63.5));
    CHECK(f.image.at(20, 60) - f.image.at(10, 60) == 5);
    CHECK(f.image.at(40, 30) - f.image.at(40, 70) == 10);
    CHECK(f.truth.area == 0);
}

TEST_CASE("Gaussian blur keeps flat areas and softens a step", "[scenes]") {
    Canvas canvas;
    canvas.fill(50);
    canvas.rect(63.5, -1, 130, 130, 150);  // columns 64 and up bright, 63 and down dark
    canvas.gaussian_blur(1.5);
    SceneFrame f;
    canvas.finish(f);
    CHECK(f.image.at(20, 64) == 50);
    CHECK(f.image.at(110, 64) == 150);
    CHECK(f.image.at(63, 64) > 60);
    CHECK(f.image.at(63, 64) < 100);
    CHECK(f.image.at(64, 64) > 100);
    CHECK(f.image.at(64, 64) < 140);
}

TEST_CASE("The generator repeats its sequence for a seed and has unit-variance noise", "[scenes]") {
    Random a(42), b(42), c(43);
    CHECK(a.next() == b.next());
    CHECK(a.next() != c.next());
    Random g(7);
    double sum = 0, sum2 = 0;
    for (int i = 0; i < 20000; ++i) {
        const double v = g.gaussian();
        sum += v;
        sum2 += v * v;
    }
    CHECK(sum / 20000 == Approx(0).margin(0.03));
    CHECK(sum2 / 20000 == Approx(1).margin(0.05));
}
