// SPDX-License-Identifier: Apache-2.0
// PolarPrior's λ_prior: where each ray from a new reference point meets the previous contour,
// against the same crossing found by trying every edge of the polygon.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/polar_prior.hpp"
#include "core/ray_table.hpp"

namespace {

using rays::Point;

// The nearest crossing of the ray m + λ(c, s), λ > 0, with any edge of the closed polygon.
double crossing(const std::vector<Point>& polygon, Point m, double c, double s) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Point a = polygon[k], b = polygon[(k + 1) % polygon.size()];
        const double ex = b.x - a.x, ey = b.y - a.y, denom = c * ey - s * ex;
        if (std::abs(denom) < 1e-12) continue;
        const double lambda = ((a.x - m.x) * ey - (a.y - m.y) * ex) / denom;
        const double t = ((a.x - m.x) * s - (a.y - m.y) * c) / denom;  // along the edge, 0 … 1
        if (lambda > 0.0 && t >= -1e-9 && t <= 1.0 + 1e-9) best = std::min(best, lambda);
    }
    return best;
}

// A star round (cx, cy): radius r0 ± dr over `lobes` lobes, `n` vertices by rising angle.
std::vector<Point> star(double cx, double cy, double r0, double dr, int lobes, int n) {
    std::vector<Point> points;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n;
        const double r = r0 + dr * std::cos(lobes * a);
        points.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return points;
}

void check_against_edges(const std::vector<Point>& polygon, Point m, int rays) {
    rays::RayTable table(rays);
    rays::PolarPrior prior(std::max(rays, static_cast<int>(polygon.size())));  // holds the whole polygon
    prior.set_polygon(polygon.data(), static_cast<int>(polygon.size()));
    prior.resample(table, m, 0.5, 200.0);
    double sum = 0.0;
    for (int i = 0; i < table.count(); ++i) {
        const double expected = crossing(polygon, m, table.cos_at(i), table.sin_at(i));
        INFO("ray " << i << " at " << table.angle(i));
        CHECK(prior.lambda(i) == Approx(expected).epsilon(1e-5));
        sum += expected;
    }
    CHECK(prior.mean_radius() == Approx(sum / table.count()).epsilon(1e-5));
}

}  // namespace

TEST_CASE("PolarPrior: each ray meets the previous contour where some edge of it crosses the ray", "[polar_prior]") {
    SECTION("a square seen from off its centre, rays through its corners") {
        const std::vector<Point> square = {{74, 74}, {54, 74}, {54, 54}, {74, 54}};  // by angle round (64, 64)
        check_against_edges(square, {64, 64}, 360);  // corners at 45°, 135° … exactly on rays
        check_against_edges(square, {60, 67}, 360);
    }
    SECTION("a concave-looking but star-shaped contour, from points round its centre") {
        const std::vector<Point> contour = star(64, 64, 20, 6, 5, 97);
        for (const Point m : {Point{64, 64}, Point{67, 61}, Point{58, 66}, Point{64, 70}})
            for (int rays : {4, 36, 360}) check_against_edges(contour, m, rays);
    }
    SECTION("the first vertex anywhere in the turn: the wrap past 2π") {
        std::vector<Point> contour = star(50, 80, 15, 3, 3, 40);
        for (int shift = 1; shift < 40; shift += 7) {
            std::vector<Point> rotated(contour.begin() + shift, contour.end());
            rotated.insert(rotated.end(), contour.begin(), contour.begin() + shift);
            check_against_edges(rotated, {52, 79}, 360);
        }
    }
}

TEST_CASE("PolarPrior: λ_prior is clamped to the search span, and a circle prior is its radius", "[polar_prior]") {
    rays::RayTable table(72);
    rays::PolarPrior prior(72);
    const std::vector<Point> square = {{94, 94}, {34, 94}, {34, 34}, {94, 34}};
    prior.set_polygon(square.data(), 4);
    prior.resample(table, {64, 64}, 2.0, 35.0);
    for (int i = 0; i < table.count(); ++i) CHECK(prior.lambda(i) <= 35.0f);
    CHECK(prior.lambda(0) == Approx(30.0));
    prior.set_circle(12.0);
    prior.resample(table, {64, 64}, 2.0, 35.0);
    for (int i = 0; i < table.count(); ++i) CHECK(prior.lambda(i) == Approx(12.0));
}
