// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "allocation_counter.hpp"
#include "io/area_scaler.hpp"

using rays::GreyImage;
using rays::kFrameSize;
using rays::io::AreaScaler;
using rays::io::Crop;

namespace {

struct Source {
    int w;
    int h;
    std::vector<std::uint8_t> px;

    Source(int width, int height, std::uint8_t fill = 0)
        : w(width), h(height), px(static_cast<std::size_t>(width * height), fill) {}
    std::uint8_t& at(int x, int y) { return px[static_cast<std::size_t>(y * w + x)]; }
};

AreaScaler make(int w, int h, Crop crop = {}) {
    std::string error;
    auto scaler = AreaScaler::make(w, h, crop, error);
    INFO(error);
    REQUIRE(scaler);
    return *scaler;
}

GreyImage scaled(const AreaScaler& scaler, const Source& src) {
    GreyImage out;
    scaler.scale(src.px.data(), src.w, out);
    return out;
}

// Independent reference in centre coordinates: processing pixel i covers
// [(i − ½)·scale + offset, (i + ½)·scale + offset]; source pixel j covers [j − ½, j + ½].
double overlap(double a0, double a1, double b0, double b1) { return std::max(0.0, std::min(a1, b1) - std::max(a0, b0)); }

double reference(const AreaScaler& s, Source& src, int i, int r) {
    const double x0 = (i - 0.5) * s.scale_x() + s.offset_x(), x1 = x0 + s.scale_x();
    const double y0 = (r - 0.5) * s.scale_y() + s.offset_y(), y1 = y0 + s.scale_y();
    double sum = 0.0;
    for (int y = static_cast<int>(std::floor(y0)); y <= static_cast<int>(std::ceil(y1)); ++y)
        for (int x = static_cast<int>(std::floor(x0)); x <= static_cast<int>(std::ceil(x1)); ++x) {
            const double a = overlap(x0, x1, x - 0.5, x + 0.5) * overlap(y0, y1, y - 0.5, y + 0.5);
            if (a > 0.0) sum += a * src.at(x, y);
        }
    return sum / (s.scale_x() * s.scale_y());
}

void check_against_reference(const AreaScaler& scaler, Source& src) {
    const GreyImage out = scaled(scaler, src);
    int compared = 0;
    for (int r = 0; r < kFrameSize; ++r)
        for (int i = 0; i < kFrameSize; ++i) {
            const double ref = reference(scaler, src, i, r);
            if (std::abs(ref - std::floor(ref) - 0.5) < 1e-3) continue;  // a tie: either rounding is right
            ++compared;
            if (out.at(i, r) != std::lround(ref)) {
                INFO("pixel " << i << "," << r << " reference " << ref);
                CHECK(int(out.at(i, r)) == std::lround(ref));
            }
        }
    CHECK(compared > kFrameSize * kFrameSize * 9 / 10);
}

}  // namespace

TEST_CASE("a constant image stays constant at any scale") {
    for (const auto& [w, h] : {std::pair{128, 128}, {192, 144}, {160, 120}, {1000, 77}, {50, 300}}) {
        INFO(w << "x" << h);
        const Source src(w, h, 173);
        const GreyImage out = scaled(make(w, h), src);
        CHECK(std::all_of(out.px.begin(), out.px.end(), [](std::uint8_t v) { return v == 173; }));
    }
}

TEST_CASE("128x128 without crop is the identity") {
    Source src(128, 128);
    std::mt19937 rng(7);
    for (auto& v : src.px) v = static_cast<std::uint8_t>(rng());
    const GreyImage out = scaled(make(128, 128), src);
    CHECK(std::equal(out.px.begin(), out.px.end(), src.px.begin()));
}

TEST_CASE("a 256x256 checkerboard averages exactly") {
    Source fine(256, 256);     // 1-pixel squares: every 2x2 block holds two of each
    Source coarse(256, 256);   // 2-pixel squares: each 2x2 block is one square
    for (int y = 0; y < 256; ++y)
        for (int x = 0; x < 256; ++x) {
            fine.at(x, y) = ((x + y) % 2) ? 200 : 10;
            coarse.at(x, y) = ((x / 2 + y / 2) % 2) ? 250 : 30;
        }
    const AreaScaler scaler = make(256, 256);
    CHECK(scaler.scale_x() == 2.0);
    CHECK(scaler.offset_x() == 0.5);
    const GreyImage from_fine = scaled(scaler, fine);
    const GreyImage from_coarse = scaled(scaler, coarse);
    for (int r = 0; r < kFrameSize; ++r)
        for (int i = 0; i < kFrameSize; ++i) {
            REQUIRE(from_fine.at(i, r) == 105);
            REQUIRE(from_coarse.at(i, r) == (((i + r) % 2) ? 250 : 30));
        }
}

TEST_CASE("a 384x128 frame maps unevenly: scale 3 by 1, offsets per the convention") {
    const AreaScaler scaler = make(384, 128);
    CHECK(scaler.scale_x() == 3.0);
    CHECK(scaler.scale_y() == 1.0);
    CHECK(scaler.offset_x() == 1.0);  // 0 + (3 − 1) / 2
    CHECK(scaler.offset_y() == 0.0);
    Source src(384, 128);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 384; ++x) src.at(x, y) = static_cast<std::uint8_t>((x * 37 + y * 11) % 251);
    const GreyImage out = scaled(scaler, src);
    for (int r = 0; r < kFrameSize; ++r)
        for (int i = 0; i < kFrameSize; ++i) {
            const int sum = src.at(3 * i, r) + src.at(3 * i + 1, r) + src.at(3 * i + 2, r);
            REQUIRE(out.at(i, r) == std::lround(sum / 3.0));  // sums of three never end in .5
        }
    // Source column 3i + 1 is the centre of processing column i: x_src = x · scale + offset.
    Source line(384, 128);
    for (int y = 0; y < 128; ++y) line.at(3 * 40 + 1, y) = 255;
    const GreyImage lit = scaled(scaler, line);
    CHECK(lit.at(40, 64) == 85);
    CHECK(lit.at(39, 64) == 0);
    CHECK(lit.at(41, 64) == 0);
}

TEST_CASE("fractional scales match an independent area integral") {
    std::mt19937 rng(12345);
    Source src(192, 144);
    for (auto& v : src.px) v = static_cast<std::uint8_t>(rng());
    check_against_reference(make(192, 144), src);

    Source wide(331, 97);
    for (auto& v : wide.px) v = static_cast<std::uint8_t>(rng());
    check_against_reference(make(331, 97), wide);
}

TEST_CASE("a crop maps with offset crop_x + (scale − 1)/2") {
    const AreaScaler scaler = make(320, 240, Crop{64, 32, 192, 192});
    CHECK(scaler.scale_x() == 1.5);
    CHECK(scaler.scale_y() == 1.5);
    CHECK(scaler.offset_x() == 64.25);
    CHECK(scaler.offset_y() == 32.25);
    std::mt19937 rng(99);
    Source src(320, 240);
    for (auto& v : src.px) v = static_cast<std::uint8_t>(rng());
    check_against_reference(scaler, src);

    // Pixels outside the crop never reach the output.
    Source framed(320, 240, 255);
    for (int y = 32; y < 224; ++y)
        for (int x = 64; x < 256; ++x) framed.at(x, y) = 40;
    const GreyImage out = scaled(scaler, framed);
    CHECK(std::all_of(out.px.begin(), out.px.end(), [](std::uint8_t v) { return v == 40; }));
}

TEST_CASE("upscaling a small crop repeats source pixels by coverage") {
    const AreaScaler scaler = make(100, 100, Crop{10, 20, 64, 64});
    CHECK(scaler.scale_x() == 0.5);
    CHECK(scaler.offset_x() == 9.75);
    Source src(100, 100);
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) src.at(x, y) = static_cast<std::uint8_t>(x + 2 * y);
    const GreyImage out = scaled(scaler, src);
    for (int r = 0; r < kFrameSize; ++r)
        for (int i = 0; i < kFrameSize; ++i) REQUIRE(out.at(i, r) == src.at(10 + i / 2, 20 + r / 2));
}

TEST_CASE("a single bright pixel keeps its mass and its position") {
    const AreaScaler scaler = make(192, 144);  // scale 1.5 by 1.125
    Source src(192, 144);
    src.at(100, 70) = 255;
    const GreyImage out = scaled(scaler, src);
    double mass = 0.0, mx = 0.0, my = 0.0;
    int lit = 0;
    for (int r = 0; r < kFrameSize; ++r)
        for (int i = 0; i < kFrameSize; ++i)
            if (const int v = out.at(i, r)) {
                mass += v;
                mx += v * i;
                my += v * r;
                ++lit;
            }
    const double area = scaler.scale_x() * scaler.scale_y();
    CHECK(lit >= 1);
    CHECK(lit <= 4);
    CHECK(std::abs(mass * area - 255.0) <= lit * 0.5 * area);  // each output rounds by at most ½
    CHECK(mx / mass == Approx((100 - scaler.offset_x()) / scaler.scale_x()).margin(0.05));
    CHECK(my / mass == Approx((70 - scaler.offset_y()) / scaler.scale_y()).margin(0.05));
}

TEST_CASE("crops outside the source are refused") {
    std::string error;
    CHECK_FALSE(AreaScaler::make(320, 240, Crop{200, 0, 128, 128}, error));
    CHECK_THAT(error, Catch::Contains("not inside the 320x240 source"));
    CHECK_FALSE(AreaScaler::make(320, 240, Crop{-1, 0, 128, 128}, error));
    CHECK_FALSE(AreaScaler::make(320, 240, Crop{0, 113, 128, 128}, error));
    CHECK_FALSE(AreaScaler::make(320, 240, Crop{0, 0, 128, -5}, error));
    CHECK_FALSE(AreaScaler::make(320, 240, Crop{5, 0, 0, 0}, error));
    CHECK_THAT(error, Catch::Contains("w = 0"));
    CHECK_FALSE(AreaScaler::make(0, 240, Crop{}, error));
    CHECK(AreaScaler::make(320, 240, Crop{192, 112, 128, 128}, error));
}

TEST_CASE("scale does not allocate") {
    const AreaScaler scaler = make(640, 480, Crop{0, 0, 640, 480});
    Source src(640, 480, 9);
    GreyImage out;
    const std::size_t before = rays::test::allocations();
    for (int k = 0; k < 3; ++k) scaler.scale(src.px.data(), src.w, out);
    CHECK(rays::test::allocations() == before);
    CHECK(out.at(5, 5) == 9);
}
