// SPDX-License-Identifier: Apache-2.0
// sample_ray's four lanes against the scalar reads they replace: the same values to the bit.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

#include "core/ray_sampler.hpp"

namespace {

using rays::FloatImage;
using rays::kFrameSize;
using rays::LikelihoodMap;

// The grey at (x, y) as the rays read it one sample at a time: the pixel at or left of / above the
// point, clamped so that its right and lower neighbours exist, and bilinear between the four.
float scalar_grey(const FloatImage& image, float x, float y) {
    const int x0 = std::clamp(static_cast<int>(x), 0, kFrameSize - 2);
    const int y0 = std::clamp(static_cast<int>(y), 0, kFrameSize - 2);
    const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
    const float* r0 = image.row(y0) + x0;
    const float* r1 = r0 + kFrameSize;
    const float top = r0[0] + fx * (r0[1] - r0[0]);
    const float bottom = r1[0] + fx * (r1[1] - r1[0]);
    return top + fy * (bottom - top);
}

struct Ray {
    float x, y, dx, dy;
    int n;
};

// Rays from random points in random directions, each as long as stays on the image; and rays that
// end exactly on the far border or start on the near one, where the reads are clamped.
std::vector<Ray> rays_to_test(std::mt19937& rng) {
    std::uniform_real_distribution<float> coord(0.0f, kFrameSize - 1.0f), angle(0.0f, 6.2831853f), step(0.5f, 1.5f);
    std::vector<Ray> rays = {{100.0f, 64.0f, 1.0f, 0.0f, 28},   // x ends at 127
                             {64.0f, 90.5f, 0.0f, 1.0f, 37},    // y ends at 126.5
                             {3.0f, 3.0f, -1.0f, -1.0f, 4},     // ends on the corner (0, 0)
                             {0.25f, 127.0f, 0.5f, -0.5f, 1},   // one sample on the border
                             {50.0f, 50.0f, 1.0f, 0.0f, 0}};    // none
    for (int k = 0; k < 300; ++k) {
        const float x = coord(rng), y = coord(rng), a = angle(rng), s = step(rng);
        const float dx = s * std::cos(a), dy = s * std::sin(a);
        int n = 0;  // as many samples as the scalar loop's positions keep on the image
        for (float px = x, py = y; px >= 0.0f && py >= 0.0f && px <= kFrameSize - 1.0f && py <= kFrameSize - 1.0f && n < 160;
             px += dx, py += dy)
            ++n;
        rays.push_back({x, y, dx, dy, n});
    }
    return rays;
}

}  // namespace

TEST_CASE("sample_ray reads the grey and the colours' log-odds as the scalar reads do, to the bit", "[rays]") {
    std::mt19937 rng(11u);
    std::uniform_real_distribution<float> grey(0.0f, 255.0f), odds(-3.0f, 3.0f);
    auto image = std::make_unique<FloatImage>();
    for (float& v : image->px) v = grey(rng);
    auto map = std::make_unique<LikelihoodMap>();
    for (float& v : map->log_odds) v = odds(rng);

    int compared = 0;
    for (const Ray& ray : rays_to_test(rng)) {
        const int room = rays::whole_lanes(ray.n);
        std::vector<float> got_grey(static_cast<std::size_t>(room) + 1, -1.0f), got_odds(got_grey.size(), -1.0f);
        rays::sample_ray(*image, map.get(), ray.x, ray.y, ray.dx, ray.dy, ray.n, got_grey.data(), got_odds.data());
        float x = ray.x, y = ray.y;
        for (int j = 0; j < ray.n; ++j, x += ray.dx, y += ray.dy) {
            INFO("ray from (" << ray.x << ", " << ray.y << ") step (" << ray.dx << ", " << ray.dy << "), sample " << j);
            REQUIRE(got_grey[j] == scalar_grey(*image, x, y));
            REQUIRE(got_odds[j] == map->at(x, y));
            ++compared;
        }
        CHECK(got_grey[room] == -1.0f);  // nothing written past the lanes' room
        CHECK(got_odds[room] == -1.0f);
    }
    CHECK(compared > 10000);
}

TEST_CASE("sample_ray without colours leaves the log-odds alone", "[rays]") {
    auto image = std::make_unique<FloatImage>();
    for (int i = 0; i < rays::kFramePixels; ++i) image->px[static_cast<std::size_t>(i)] = static_cast<float>(i % 251);
    std::vector<float> got_grey(8, -1.0f), got_odds(8, -1.0f);
    rays::sample_ray(*image, nullptr, 10.5f, 20.0f, 1.0f, 0.25f, 6, got_grey.data(), got_odds.data());
    float x = 10.5f, y = 20.0f;
    for (int j = 0; j < 6; ++j, x += 1.0f, y += 0.25f) CHECK(got_grey[j] == scalar_grey(*image, x, y));
    CHECK(std::all_of(got_odds.begin(), got_odds.end(), [](float v) { return v == -1.0f; }));
}
