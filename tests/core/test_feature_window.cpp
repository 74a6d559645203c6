// SPDX-License-Identifier: Apache-2.0
// What the correlation filter sees of a window (core/feature_window.hpp), on images drawn here: a
// rim's orientation, the same looks under other light, and colour.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>

#include "core/feature_window.hpp"
#include "support/block_texture.hpp"

namespace {

using rays::Chroma;
using rays::FeatureWindow;
using rays::FloatImage;
using rays::Point;

constexpr int kN = FeatureWindow::kSize;
constexpr Point kCentre{64.0, 64.0};
constexpr double kOneSamplePerPixel = kN;  // a window this wide has its samples on the pixels
constexpr int kGreyPairs = (1 + FeatureWindow::kOrientations + 1) / 2;

using Pairs = std::array<FeatureWindow::Spectrum, FeatureWindow::kPairs>;

// Channel c at window sample (u, v), the Hann taper taken off again (u, v > 0).
double channel(const Pairs& pairs, int c, int u, int v) {
    const std::complex<float> packed = pairs[static_cast<std::size_t>(c / 2)][static_cast<std::size_t>(v * kN + u)];
    auto hann = [](int k) { return 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * k / kN)); };
    return (c % 2 == 0 ? packed.real() : packed.imag()) / (hann(u) * hann(v));
}

// The orientation channel of bin k (its angle kπ/K from the x axis).
int orientation(int k) { return 1 + k; }

// Grey `left` on x < 64 and `right` from there on.
std::unique_ptr<FloatImage> step_image(float left, float right) {
    auto image = std::make_unique<FloatImage>();
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) image->at(x, y) = x < 64 ? left : right;
    return image;
}

}  // namespace

TEST_CASE("FeatureWindow: a rim shows in the orientation across it, whichever side is brighter") {
    auto window = std::make_unique<FeatureWindow>();
    auto pairs = std::make_unique<Pairs>();
    const Chroma grey;
    window->fill(*step_image(50.0f, 150.0f), grey, kCentre, kOneSamplePerPixel, kGreyPairs, *pairs);
    // The rim lies between samples 15 and 16 (pixels 63 and 64): its gradient points along x.
    const double across = channel(*pairs, orientation(0), 16, 16);
    CHECK(across > 1.0);
    CHECK(channel(*pairs, orientation(0), 15, 16) == Approx(across));
    CHECK(channel(*pairs, orientation(3), 16, 16) == Approx(0.0).margin(1e-6));  // along the rim
    CHECK(channel(*pairs, orientation(1), 16, 16) == Approx(0.5 * across));      // 30° off: cos 60°
    CHECK(channel(*pairs, orientation(0), 6, 16) == Approx(0.0).margin(1e-6));   // away from it: nothing

    auto reversed = std::make_unique<Pairs>();
    window->fill(*step_image(150.0f, 50.0f), grey, kCentre, kOneSamplePerPixel, kGreyPairs, *reversed);
    for (int k = 0; k < FeatureWindow::kOrientations; ++k)
        CHECK(channel(*reversed, orientation(k), 16, 16) == Approx(channel(*pairs, orientation(k), 16, 16)));
    // Grey is signed: the brighter side changes.
    CHECK(channel(*pairs, 0, 20, 16) > 0.0);
    CHECK(channel(*reversed, 0, 20, 16) < 0.0);
}

TEST_CASE("FeatureWindow: the same texture under other light and contrast looks the same") {
    auto dim = std::make_unique<FloatImage>();
    auto bright = std::make_unique<FloatImage>();
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) {
            const float texture = static_cast<float>(rays::test::block_hash(x / 3, y / 3, 5u) % 80);
            dim->at(x, y) = 30.0f + texture;
            bright->at(x, y) = 2.5f * (30.0f + texture) + 20.0f;
        }
    auto window = std::make_unique<FeatureWindow>();
    auto a = std::make_unique<Pairs>();
    auto b = std::make_unique<Pairs>();
    const Chroma grey;
    window->fill(*dim, grey, kCentre, 40.0, kGreyPairs, *a);
    window->fill(*bright, grey, kCentre, 40.0, kGreyPairs, *b);
    int differing = 0;
    for (int c = 0; c < 1 + FeatureWindow::kOrientations; ++c)
        for (int v = 1; v < kN; v += 3)
            for (int u = 1; u < kN; u += 3) {
                const double x = channel(*a, c, u, v), y = channel(*b, c, u, v);
                if (std::abs(x - y) > 1e-3 * (1.0 + std::abs(x))) ++differing;
            }
    CHECK(differing == 0);
    CHECK(std::abs(channel(*a, 0, 16, 16)) + std::abs(channel(*a, 0, 10, 20)) > 0.1);  // not all flat
}

TEST_CASE("FeatureWindow: colour channels tell a window's two colours apart, and grey ones do not see colour") {
    auto image = step_image(100.0f, 100.0f);
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) image->at(x, y) = static_cast<float>(90 + (x * 7 + y * 13) % 30);
    Chroma colour;
    colour.present = true;
    for (int j = 0; j < rays::kChromaSize; ++j)
        for (int i = 0; i < rays::kChromaSize; ++i) {
            const auto k = static_cast<std::size_t>(j * rays::kChromaSize + i);
            colour.u[k] = i < 32 ? 100 : 160;  // less blue left of x = 64, more right of it
            colour.v[k] = 128;
        }
    auto window = std::make_unique<FeatureWindow>();
    auto in_colour = std::make_unique<Pairs>();
    auto in_grey = std::make_unique<Pairs>();
    window->fill(*image, colour, kCentre, kOneSamplePerPixel, FeatureWindow::kPairs, *in_colour);
    window->fill(*image, Chroma{}, kCentre, kOneSamplePerPixel, kGreyPairs, *in_grey);
    const int cb = 1 + FeatureWindow::kOrientations, cr = cb + 1;
    CHECK(channel(*in_colour, cb, 8, 16) < -0.5);
    CHECK(channel(*in_colour, cb, 24, 16) > 0.5);
    CHECK(channel(*in_colour, cr, 8, 16) == Approx(0.0).margin(1e-6));  // one Cr throughout: nothing
    for (int c = 0; c < 1 + FeatureWindow::kOrientations; ++c)
        CHECK(channel(*in_colour, c, 12, 9) == Approx(channel(*in_grey, c, 12, 9)));
}
