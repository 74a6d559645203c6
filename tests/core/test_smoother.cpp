// SPDX-License-Identifier: Apache-2.0
// The Gaussian pre-smoothing G_σ of eq. 4.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "core/gaussian_smoother.hpp"

namespace {

using rays::FloatImage;
using rays::GaussianSmoother;
using rays::GreyImage;
using rays::kFrameSize;

GreyImage impulse(int cx, int cy, std::uint8_t value) {
    GreyImage image;
    image.at(cx, cy) = value;
    return image;
}

}  // namespace

TEST_CASE("GaussianSmoother keeps a constant image constant, borders included", "[smoother]") {
    GaussianSmoother smoother;
    GreyImage image;
    image.px.fill(137);
    FloatImage out;
    for (double sigma : {0.5, 1.0, 2.0, 2.6}) {
        smoother.set_sigma(sigma);
        smoother.smooth(image, out);
        INFO("sigma " << sigma);
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) REQUIRE(out.at(x, y) == Approx(137.0f).epsilon(1e-5));
    }
}

TEST_CASE("GaussianSmoother spreads a bright pixel symmetrically and keeps its mass", "[smoother]") {
    GaussianSmoother smoother;
    constexpr int cx = 60, cy = 70;
    const GreyImage image = impulse(cx, cy, 255);
    FloatImage out;
    for (double sigma : {1.0, 1.5, 2.5}) {
        smoother.set_sigma(sigma);
        smoother.smooth(image, out);
        INFO("sigma " << sigma);
        double mass = 0, var_x = 0, var_y = 0;
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const double v = out.at(x, y);
                mass += v;
                var_x += v * (x - cx) * (x - cx);
                var_y += v * (y - cy) * (y - cy);
            }
        CHECK(mass == Approx(255.0).epsilon(1e-4));
        // The spread is the σ asked for (a sampled Gaussian cut at 3σ is a little narrower).
        CHECK(std::sqrt(var_x / mass) == Approx(sigma).epsilon(0.05));
        CHECK(std::sqrt(var_y / mass) == Approx(sigma).epsilon(0.05));
        CHECK(out.at(cx, cy) < 255.0f * 0.5f / (sigma * sigma));
        for (int d = 1; d <= 4; ++d) {
            const float right = out.at(cx + d, cy), left = out.at(cx - d, cy);
            const float down = out.at(cx, cy + d), up = out.at(cx, cy - d);
            CHECK(left == Approx(right).epsilon(1e-5));
            CHECK(up == Approx(down).epsilon(1e-5));
            CHECK(up == Approx(right).epsilon(1e-5));
            CHECK(out.at(cx + d, cy + d) == Approx(out.at(cx - d, cy - d)).epsilon(1e-5));
            CHECK(right < out.at(cx + d - 1, cy));  // falls off from the centre
        }
        CHECK(out.at(cx + 12, cy) == 0.0f);  // beyond the kernel radius
    }
}

TEST_CASE("GaussianSmoother with sigma 0 copies the image", "[smoother]") {
    GaussianSmoother smoother;
    std::mt19937 rng(3u);
    std::uniform_int_distribution<int> grey(0, 255);
    GreyImage image;
    for (auto& p : image.px) p = static_cast<std::uint8_t>(grey(rng));
    FloatImage out;
    smoother.set_sigma(0.0);
    CHECK(smoother.sigma() == 0.0);
    smoother.smooth(image, out);
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) REQUIRE(out.at(x, y) == static_cast<float>(image.at(x, y)));
}
