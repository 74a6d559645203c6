// SPDX-License-Identifier: Apache-2.0
// The tracker's contour quality on the generated scenes (the acceptance figures), measured
// against the scenes' own ground-truth masks. Frames not in the tracking state score 0.
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>

#include "core/tracker.hpp"
#include "scenes/scene.hpp"

using namespace rays;

namespace {

struct Score {
    double mean_iou = 0;
    int losses = 0;
    int tracking = 0;
};

Score run_scene(const char* name, int lost_check_from = -1, int lost_check_to = -1, int* losses_in_window = nullptr,
                const TrackerConfig& config = {}) {
    auto scene = scenes::make_scene(name);
    SteadyClock clock;
    Tracker tracker(config, clock);
    scenes::SceneFrame f;
    Score s;
    double sum = 0;
    for (int i = 0; i < scene->frame_count(); ++i) {
        scene->render(i, f);
        const FrameResult& r = tracker.process(f.image, TimePoint::max());
        if (r.state == TrackState::Lost) {
            ++s.losses;
            if (losses_in_window && i >= lost_check_from && i < lost_check_to) ++*losses_in_window;
        }
        if (!r.has_contour) continue;
        ++s.tracking;
        std::vector<Point> polygon(tracker.contour().size);
        for (int k = 0; k < tracker.contour().size; ++k) polygon[k] = tracker.contour().points[k].p;
        sum += scenes::polygon_mask_iou(polygon, f.mask);
    }
    s.mean_iou = sum / scene->frame_count();
    std::printf("%-14s mean IoU %.3f, %d tracking frames of %d, %d losses\n", name, s.mean_iou, s.tracking,
                scene->frame_count(), s.losses);
    return s;
}

// `name` scores at least `least` with the default config, and 0.15 more than with `without` (the
// default with `term` switched off).
void check_gain(const char* name, const TrackerConfig& without, const char* term, double least) {
    const double off = run_scene(name, -1, -1, nullptr, without).mean_iou, on = run_scene(name).mean_iou;
    INFO(name << " mean IoU without " << term << " " << off << ", with " << on);
    CHECK(on >= least);
    CHECK(on >= off + 0.15);
}

}  // namespace

TEST_CASE("Easy scenes: mean IoU at least 0.85", "[quality]") {
    CHECK(run_scene("clutter").mean_iou >= 0.85);
    CHECK(run_scene("star").mean_iou >= 0.85);
    CHECK(run_scene("noise-blur").mean_iou >= 0.85);
}

TEST_CASE("Hard scenes: mean IoU at least 0.6", "[quality]") {
    CHECK(run_scene("weak-contrast").mean_iou >= 0.6);
    CHECK(run_scene("shadow").mean_iou >= 0.6);
    CHECK(run_scene("occluder").mean_iou >= 0.6);
    CHECK(run_scene("speed-ramp").mean_iou >= 0.6);
    CHECK(run_scene("walker-pole").mean_iou >= 0.6);
    CHECK(run_scene("approach").mean_iou >= 0.6);
}

TEST_CASE("The jump cost lets a walker's legs and head into the contour", "[quality]") {
    // Eq. 9 whole charges the flanks of a thin leg more than its rays gain, so the contour keeps to
    // the torso; truncated between edges (rays.jump_cost) the legs come in. Measured: 0.517 → 0.804.
    TrackerConfig whole;
    whole.tunables.rays.jump_cost = 0.0;
    check_gain("walker-pole", whole, "the jump cost", 0.6);
}

TEST_CASE("The still camera's foreground keeps a target whose rim is weaker than its background's edges", "[quality]") {
    // camouflage: the ellipse is 12 grey levels below a texture of ±25; its edges alone lose to the
    // texture's. Against the learned background it stands out. Measured: 0.473 → 0.713.
    TrackerConfig edges_only;
    edges_only.tunables.rays.foreground_weight = 0.0;
    check_gain("camouflage", edges_only, "the foreground term", 0.65);
}

TEST_CASE("A target moving 8 px/frame is kept without a loss", "[quality]") {
    int losses = 0;  // speed-ramp holds 8 px/frame over frames 170–229
    run_scene("speed-ramp", 170, 230, &losses);
    CHECK(losses == 0);
}
