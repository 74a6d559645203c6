// SPDX-License-Identifier: Apache-2.0
// Polygon scoring as ../shared/tools/score-contours.py does it: even-odd fill at pixel centres.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "scenes/render.hpp"

using namespace rays;
using namespace rays::scenes;

namespace {

GreyImage square_mask(int x0, int y0, int x1, int y1) {  // pixels x0..x1 × y0..y1 set
    GreyImage mask{};
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) mask.at(x, y) = 255;
    return mask;
}

std::vector<Point> circle(double cx, double cy, double r, int points) {
    std::vector<Point> polygon;
    for (int i = 0; i < points; ++i) {
        const double a = 2 * std::numbers::pi * i / points;
        polygon.push_back({cx + r * std::cos(a), cy + r * std::sin(a)});
    }
    return polygon;
}

}  // namespace

TEST_CASE("A square polygon fills the pixel centres strictly inside on its left and top", "[scenes]") {
    // The vertical edges span rows 10..19 ((y0 > y) != (y1 > y)) and toggle the pixels x < 20 and x < 10.
    const std::vector<Point> square{{10, 10}, {20, 10}, {20, 20}, {10, 20}};
    CHECK(polygon_mask_iou(square, square_mask(10, 10, 19, 19)) == 1.0);
    CHECK(polygon_mask_iou(square, square_mask(10, 10, 20, 20)) == Approx(100.0 / 121.0));
    const Point c = polygon_centroid_px(square);
    CHECK(c.x == 14.5);
    CHECK(c.y == 14.5);
}

TEST_CASE("The fill is even-odd: a hole traced inside the outline stays empty", "[scenes]") {
    // Outer square 10..30 and inner square 15..25 joined by a zero-width cut along y = 10..15 at x = 15.
    const std::vector<Point> ring{{10, 10}, {15, 10}, {15, 15}, {15, 25}, {25, 25}, {25, 15}, {15, 15},
                                  {15, 10}, {30, 10}, {30, 30}, {10, 30}};
    GreyImage expected = square_mask(10, 10, 29, 29);
    for (int y = 15; y <= 24; ++y)
        for (int x = 15; x <= 24; ++x) expected.at(x, y) = 0;
    CHECK(polygon_mask_iou(ring, expected) == 1.0);
}

TEST_CASE("A polygon tracing a rendered disc scores IoU above 0.95 and a shifted one lower", "[scenes]") {
    Canvas canvas;
    canvas.fill(30);
    canvas.paint(Disc{60.3, 70.6, 16}, 220, true);
    SceneFrame f;
    canvas.finish(f);
    const auto traced = circle(60.3, 70.6, 16, 72);
    CHECK(polygon_mask_iou(traced, f.mask) > 0.95);
    const double shifted = polygon_mask_iou(circle(64.3, 70.6, 16, 72), f.mask);
    CHECK(shifted < 0.8);
    CHECK(shifted > 0.5);
    CHECK(polygon_mask_iou(circle(110, 20, 8, 36), f.mask) == 0.0);
    const Point c = polygon_centroid_px(traced);
    CHECK(c.x == Approx(f.truth.cx).margin(0.1));
    CHECK(c.y == Approx(f.truth.cy).margin(0.1));
}

TEST_CASE("Fewer than three points score zero and have no centroid", "[scenes]") {
    const GreyImage full = square_mask(0, 0, kFrameSize - 1, kFrameSize - 1);
    CHECK(polygon_mask_iou(std::vector<Point>{}, full) == 0.0);
    CHECK(polygon_mask_iou(std::vector<Point>{{1, 1}, {100, 100}}, full) == 0.0);
    CHECK(std::isnan(polygon_centroid_px(std::vector<Point>{{1, 1}, {100, 100}}).x));
}
