// SPDX-License-Identifier: Apache-2.0
// The motion layers on scenes drawn here: a textured target moving one way across a textured world
// the camera pans the other way. The map must call the whole target the target from a contour round
// part of it, call the world the background, and say nothing where the two move alike; in the
// tracker, a target of the world's own texture and colour must be found by its motion alone.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numbers>

#include "core/motion_layers.hpp"
#include "core/tracker.hpp"
#include "support/block_texture.hpp"
#include "support/camouflaged_target_scene.hpp"
#include "support/map_means.hpp"

namespace {

using rays::Contour;
using rays::FloatImage;
using rays::LikelihoodMap;
using rays::MotionLayers;
using rays::Point;

constexpr double kRadius = 14.0;  // the target's, px

// The view at x shows the world at x + pan; the target is a disc of its own texture centred at `target`.
void draw(FloatImage& image, Point target, Point pan) {
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) {
            const double dx = x - target.x, dy = y - target.y;
            const bool on = dx * dx + dy * dy <= kRadius * kRadius;
            image.at(x, y) = static_cast<float>(on ? rays::test::smooth_blocks(dx, dy, 7u, 4.0, 40, 160)
                                                   : rays::test::smooth_blocks(x + pan.x, y + pan.y, 1u, 5.0, 40, 160));
        }
}

// A contour round part of the target: a circle of `radius` about `centre`, shot from there.
void circle(Contour& contour, Point centre, double radius) {
    contour.size = 64;
    contour.ref = centre;
    for (int i = 0; i < contour.size; ++i) {
        const double a = 2.0 * std::numbers::pi * i / contour.size;
        contour.points[static_cast<std::size_t>(i)].p = {centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
    }
    rays::polygon_area_centroid(contour.points.data(), contour.size, contour.area, contour.centroid);
}

rays::test::MapMeans read(const MotionLayers& layers, Point target) {
    LikelihoodMap map;
    layers.add_to(map, {0.0, 0.0});
    return rays::test::map_means(map, target);
}

struct Run {
    std::unique_ptr<FloatImage> before = std::make_unique<FloatImage>(), now = std::make_unique<FloatImage>();
    Contour contour{rays::TrackerCapacity{}};
    MotionLayers layers;

    // Frames 0 … frames: the target moves by `step` a frame, the view by `view` (this(x) = before(x − view)).
    // The layers are told the centroid moved by `told` (the real step when absent).
    Point run(int frames, Point step, Point view, const Point* told = nullptr) {
        const Point start{50.0, 64.0};
        draw(*before, start, {0.0, 0.0});
        Point target = start;
        for (int f = 1; f <= frames; ++f) {
            target = {start.x + f * step.x, start.y + f * step.y};
            draw(*now, target, {-f * view.x, -f * view.y});
            circle(contour, target, 0.35 * kRadius);
            layers.update(*now, *before, contour, told ? *told : step, view);
            std::swap(before, now);
        }
        return target;
    }
};

}  // namespace

TEST_CASE("MotionLayers calls the whole target the target from a contour round part of it", "[motion_layers]") {
    Run r;
    const Point target = r.run(6, {1.0, 0.0}, {-1.5, 0.5});
    REQUIRE(r.layers.valid());
    const rays::test::MapMeans m = read(r.layers, target);
    INFO("target " << m.target << ", background " << m.background);
    CHECK(m.target > 1.5);       // beyond the contour, on the target: it moves with it
    CHECK(m.background < -1.5);  // the world moves with the view
    CHECK(std::abs(r.layers.target_shift().x - 1.0) <= 0.25);
    CHECK(std::abs(r.layers.target_shift().y) <= 0.25);
}

TEST_CASE("MotionLayers finds the target's shift where the centroid's is off by four pixels", "[motion_layers]") {
    Run r;
    const Point told{5.0, -1.0};  // a contour that changed shape moved its centroid further than the target
    const Point target = r.run(4, {1.0, 0.0}, {-1.5, 0.5}, &told);
    INFO("shift " << r.layers.target_shift().x << ", " << r.layers.target_shift().y);
    CHECK(std::abs(r.layers.target_shift().x - 1.0) <= 0.25);
    CHECK(std::abs(r.layers.target_shift().y) <= 0.25);
    CHECK(read(r.layers, target).target > 1.0);
}

TEST_CASE("MotionLayers says nothing where the target and the view move alike", "[motion_layers]") {
    Run r;
    r.run(6, {1.0, 0.5}, {1.0, 0.5});
    REQUIRE(r.layers.valid());
    CHECK(read(r.layers, {56.0, 67.0}).magnitude < 0.05);
}

TEST_CASE("MotionLayers moves its map by whole cells exactly and takes nothing from beyond the image", "[motion_layers]") {
    Run r;
    const Point target = r.run(6, {1.0, 0.0}, {-1.5, 0.5});
    REQUIRE(r.layers.valid());
    LikelihoodMap here, moved, gone;
    r.layers.add_to(here, {0.0, 0.0});
    // Moved 2 px (one cell) to the right: each cell holds its left neighbour's value; the first
    // column, whose source is off the map, nothing.
    r.layers.add_to(moved, {2.0, 0.0});
    for (int j = 0; j < rays::kChromaSize; ++j) {
        CHECK(moved.cell(0, j) == 0.0f);
        for (int i = 1; i < rays::kChromaSize; ++i) REQUIRE(moved.cell(i, j) == here.cell(i - 1, j));
    }
    // Moved off the frame altogether: nothing anywhere.
    r.layers.add_to(gone, {200.0, -200.0});
    for (float v : gone.log_odds) REQUIRE(v == 0.0f);
    // A view that moved beyond the image brings every place from off it: no evidence, so the map
    // only moves with the target and forgets (bilinear moves never add to its total magnitude).
    const double before = read(r.layers, target).magnitude;
    r.layers.update(*r.before, *r.before, r.contour, {0.0, 0.0}, {200.0, 200.0});
    const double after = read(r.layers, target).magnitude;
    INFO("mean |log-odds| " << before << " -> " << after);
    CHECK(before > 0.1);
    CHECK(after <= 0.9 * before + 1e-6);
}

namespace {

// Tracks the camouflaged target from its centre; the contours' mean overlap with the target over
// the last `scored` of `frames` frames (a frame not tracked scores 0).
double track_camouflaged(bool layers, int frames, int scored) {
    rays::TrackerConfig config;
    config.tunables.rays.motion_layers = layers;
    const rays::SteadyClock clock;
    rays::Tracker tracker(config, clock);
    const auto scene = std::make_unique<rays::test::CamouflagedTargetScene>();
    tracker.start_at(scene->centre(0));
    double sum = 0.0;
    for (int f = 0; f < frames; ++f) {
        scene->draw(f);
        const bool tracking = tracker.process(scene->image, scene->chroma, rays::TimePoint::max()).state == rays::TrackState::Tracking;
        if (f >= frames - scored && tracking) sum += rays::test::contour_mask_iou(tracker.contour(), scene->mask);
    }
    return sum / scored;
}

}  // namespace

TEST_CASE("Tracker finds the rim of a target camouflaged in grey and colour by its motion while the view pans", "[motion_layers][tracker]") {
    const double with = track_camouflaged(true, 40, 20), without = track_camouflaged(false, 40, 20);
    INFO("overlap with the layers " << with << ", without " << without);
    CHECK(with > 0.8);
    CHECK(without < 0.6);
}
