// SPDX-License-Identifier: Apache-2.0
// What the tracker learns of its target (TargetModel) and what the previous contour tells the next
// extraction (PolarPrior): the parts a thin target depends on.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/contour.hpp"
#include "core/polar_prior.hpp"
#include "core/ray_table.hpp"
#include "core/target_model.hpp"

using namespace rays;

namespace {

constexpr int kRays = 64;

// A ring of edges round the origin: even rays at λ = `near_px` with inside grey `near_grey`, odd rays
// at λ = 10 px with inside grey 40.
Contour ring(float near_px, float near_grey) {
    TrackerCapacity capacity;
    Contour c(capacity);
    c.size = kRays;
    for (int i = 0; i < kRays; ++i) {
        ContourPoint& p = c.points[i];
        p.phi = 2.0f * std::numbers::pi_v<float> * (static_cast<float>(i) + 0.5f) / kRays;  // off the bin borders
        const bool near = i % 2 == 0;
        p.lambda = near ? near_px : 10.0f;
        p.grad = -20.0f;
        p.inside_mean = near ? near_grey : 40.0f;
        p.inside_sd = 2.0f;
        p.outside_mean = 120.0f;
    }
    return c;
}

}  // namespace

TEST_CASE("TargetModel learns the inside only from edges whose rays saw it clear of the rim", "[target_model]") {
    std::vector<float> scratch(static_cast<std::size_t>(TrackerCapacity{}.max_rays));
    // Edges 2 px from m have only rim-blurred samples inside (here 100, half-way to the background):
    // they leave the learned inside grey at the far edges' 40.
    TargetModel model;
    model.learn(ring(2.0f, 100.0f), scratch);
    REQUIRE(model.valid);
    for (float m : model.inside_mean) CHECK(m == Approx(40.0f));
    for (float m : model.outside_mean) CHECK(m == Approx(120.0f));  // the band outside is learned from every edge
    // Edges 6 px from m count in full: the mean is then half-way.
    TargetModel full;
    full.learn(ring(6.0f, 100.0f), scratch);
    float sum = 0.0f;
    for (float m : full.inside_mean) sum += m;
    CHECK(sum / TargetModel::kBins == Approx(70.0f));
    // Every edge 2 px from m: nothing is learned of the inside, the seeded looks stay.
    TargetModel seeded;
    seeded.valid = true;
    seeded.inside_mean.fill(55.0f);
    seeded.inside_spread = 3.0f;
    Contour thin = ring(2.0f, 100.0f);
    for (int i = 0; i < kRays; ++i) thin.points[i].lambda = 2.0f;
    seeded.learn(thin, scratch);
    for (float m : seeded.inside_mean) CHECK(m == Approx(55.0f));
    CHECK(seeded.inside_spread == Approx(3.0f));
    CHECK(seeded.polarity[0] < 0.0f);  // the polarity is learned all the same
}

TEST_CASE("PolarPrior marks the rays that cross the previous contour where it had no edge", "[polar_prior]") {
    // A square of 8 points round (64, 64), the point straight right of m (angle 0) without an edge.
    const Point m{64.0, 64.0};
    const Point square[] = {{84, 64}, {84, 84}, {64, 84}, {44, 84}, {44, 64}, {44, 44}, {64, 44}, {84, 44}};
    const unsigned char open[] = {1, 0, 0, 0, 0, 0, 0, 0};
    RayTable table(360);
    table.set_count(360);
    PolarPrior prior(360);
    prior.set_polygon(square, 8, open);
    prior.resample(table, m, 2.0, 60.0);
    int opened = 0;
    for (int i = 0; i < table.count(); ++i) {
        const double deg = table.angle(i) * 180.0 / std::numbers::pi;
        // The two sides that meet at the open point span 45° either side of it.
        const bool beside = deg < 45.0 - 1e-6 || deg > 315.0 + 1e-6;
        if (beside) CHECK(prior.open(i));
        if (deg > 46.0 && deg < 314.0) CHECK_FALSE(prior.open(i));
        opened += prior.open(i);
    }
    CHECK(opened >= 88);
    CHECK(opened <= 92);
    // Without flags nothing is open.
    prior.set_polygon(square, 8);
    prior.resample(table, m, 2.0, 60.0);
    for (int i = 0; i < table.count(); ++i) CHECK_FALSE(prior.open(i));
}
