// SPDX-License-Identifier: Apache-2.0
// RayProfiler's 1-D search on rays drawn here: edge candidates (eq. 7/12/13) and the colour split.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "core/ray_hypotheses.hpp"

namespace {

using rays::FloatImage;
using rays::Hypothesis;
using rays::LikelihoodMap;
using rays::RayProfiler;

constexpr rays::Point kM{20.0, 64.0};  // the rays below run from here along +x: λ = x − 20

// Columns of grey: `level(x)` for every row.
template <class Level>
std::unique_ptr<FloatImage> columns(Level level) {
    auto image = std::make_unique<FloatImage>();
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) image->at(x, y) = level(x);
    return image;
}

RayProfiler profiler(int hypotheses) {
    rays::RaysTunables t;
    t.hypotheses = hypotheses;
    RayProfiler p{rays::TrackerCapacity{}};
    REQUIRE(p.configure(t));
    return p;
}

}  // namespace

TEST_CASE("RayProfiler keeps the strongest edges along a ray, strongest first, each where its step is", "[rays]") {
    // Steps of 30 up at x = 30, 80 down at x = 45 and 20 up at x = 60, each a two-pixel ramp;
    // a ripple of 1 grey (below the edge floor) everywhere.
    auto image = columns([](int x) {
        float v = 100.0f + ((x % 3) == 0 ? 1.0f : 0.0f);
        v += x >= 31 ? 30.0f : x == 30 ? 15.0f : 0.0f;
        v -= x >= 46 ? 80.0f : x == 45 ? 40.0f : 0.0f;
        v += x >= 61 ? 20.0f : x == 60 ? 10.0f : 0.0f;
        return v;
    });
    RayProfiler rays = profiler(3);
    Hypothesis out[6];
    float end = 0.0f;
    const int n = rays.shoot(*image, nullptr, nullptr, kM, 1.0, 0.0, 0.0f, 60.0f, out, end);
    REQUIRE(n == 3);
    CHECK(end == Approx(60.0f));
    CHECK(out[0].lambda == Approx(25.0f).margin(0.5f));  // x = 45, the strongest, darker outside
    CHECK(out[0].grad < 0.0f);
    CHECK(out[1].lambda == Approx(10.0f).margin(0.5f));  // x = 30
    CHECK(out[1].grad > 0.0f);
    CHECK(out[2].lambda == Approx(40.0f).margin(0.5f));  // x = 60
    CHECK(std::abs(out[0].grad) > std::abs(out[1].grad));
    CHECK(std::abs(out[1].grad) > std::abs(out[2].grad));
    // The inside of the step at x = 30 is the grey before it; its outside the grey after it.
    CHECK(out[1].inside_mean == Approx(100.33f).margin(0.5f));
    CHECK(out[1].outside_mean == Approx(130.33f).margin(0.5f));

    // Only what lies beyond `lambda_from` is searched, and no further than the limit.
    const int beyond = rays.shoot(*image, nullptr, nullptr, kM, 1.0, 0.0, 20.0f, 35.0f, out, end);
    REQUIRE(beyond == 1);
    CHECK(out[0].lambda == Approx(25.0f).margin(0.5f));
    CHECK(end == Approx(35.0f));
}

TEST_CASE("RayProfiler's colour split is the first place where the ray's summed log-odds peak", "[rays]") {
    // No grey edges at all; the colours say target up to x ≈ 40, nothing either way to x ≈ 49,
    // background beyond: every boundary on the even stretch sums the same log-odds, and the split
    // is the first of them, x = 41 (where the interpolated log-odds first reach 0).
    auto image = columns([](int) { return 90.0f; });
    auto map = std::make_unique<LikelihoodMap>();
    for (int j = 0; j < LikelihoodMap::kSize; ++j)
        for (int i = 0; i < LikelihoodMap::kSize; ++i) {
            const float centre = 2.0f * static_cast<float>(i) + 0.5f;  // cell i's centre, in pixels
            map->log_odds[static_cast<std::size_t>(j * LikelihoodMap::kSize + i)] = centre < 40.0f ? 2.0f : centre < 50.0f ? 0.0f : -2.0f;
        }
    RayProfiler rays = profiler(3);
    Hypothesis out[6];
    float end = 0.0f;
    const int n = rays.shoot(*image, nullptr, map.get(), kM, 1.0, 0.0, 0.0f, 60.0f, out, end);
    REQUIRE(n == 1);
    CHECK(out[0].lambda == Approx(21.0f));  // x = 41
    CHECK(out[0].appearance == Approx(0.0f).margin(1e-5f));
    // A rim further out gives up what the samples between say; on the even stretch, nothing.
    CHECK(rays.appearance_at(25.0f) == Approx(0.0f).margin(1e-4f));
    CHECK(rays.appearance_at(15.0f) > 5.0f);  // six samples of log-odds 2 given to the background
    CHECK(rays.appearance_at(40.0f) > 5.0f);  // the background's −2 counted as the target's
}
