// SPDX-License-Identifier: Apache-2.0
// The tracker while the view moves, on scenes drawn here: a dark textured target on a bright
// textured world that the camera pans across. Frame differencing must align the frames first, and
// a target lost while the camera turned is found again by its looks, wherever it is in the frame.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>

#include "core/tracker.hpp"
#include "scenes/scene.hpp"
#include "support/block_texture.hpp"

namespace {

using rays::Point;
using rays::SteadyClock;
using rays::Tracker;
using rays::TrackerConfig;
using rays::TrackState;
using rays::test::smooth_blocks;

struct PanningScene {
    static constexpr double kA = 12.0, kB = 9.0;  // the target's half axes, px
    SteadyClock clock;
    Tracker tracker{TrackerConfig{}, clock};
    std::unique_ptr<rays::scenes::SceneFrame> frame = std::make_unique<rays::scenes::SceneFrame>();
    double size = 1.0;  // the target's size, as a share of kA, kB
    bool poles = false;  // dark poles 2 kPoleHalfWidth px wide stand in the world every kPoleEvery px: edges that show any drift

    static constexpr int kPoleEvery = 24, kPoleHalfWidth = 3;

    // Draws the view from `pan` (the view at x shows the world at x + pan) with the target centred
    // at `target` in the view (none when `hidden`), and tracks it.
    TrackState step(Point pan, Point target, bool hidden = false) {
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                const double u = (x - target.x) / (size * kA), v = (y - target.y) / (size * kB);
                const bool on = !hidden && u * u + v * v <= 1.0;
                const double world_x = x + pan.x;
                const double pole = world_x - kPoleEvery * std::floor(world_x / kPoleEvery);  // 0 … kPoleEvery
                const double dark = poles ? std::clamp(kPoleHalfWidth + 0.5 - std::abs(pole - kPoleHalfWidth), 0.0, 1.0) : 0.0;
                const double grey = on ? smooth_blocks(x - target.x, y - target.y, 7u, 4.0, 20, 50)
                                       : (1.0 - dark) * smooth_blocks(world_x, y + pan.y, 1u, 6.0, 100, 130) + dark * 25.0;
                frame->image.at(x, y) = static_cast<std::uint8_t>(std::lround(grey));
                frame->mask.at(x, y) = on ? 255 : 0;
            }
        return tracker.process(frame->image, rays::TimePoint::max()).state;
    }

    bool on_target() const {
        const Point c = tracker.contour().centroid;
        const int px = static_cast<int>(std::lround(c.x)), py = static_cast<int>(std::lround(c.y));
        return px >= 0 && py >= 0 && px < rays::kFrameSize && py < rays::kFrameSize && frame->mask.at(px, py) == 255;
    }
};

}  // namespace

TEST_CASE("Tracker detects a mover while the view pans, on frames aligned by the view's shift", "[tracker][view]") {
    // The camera pans 2 px a frame; the target crosses the world at 1.5 px a frame the other way.
    // Differencing the frames as they come would show the whole textured world moving.
    PanningScene run;
    int found_at = -1;
    for (int i = 0; i < 12 && found_at < 0; ++i) {
        const TrackState state = run.step({2.0 * i, 0.0}, {40.0 - 0.5 * i, 64.0});
        if (state == TrackState::Tracking) found_at = i;
    }
    INFO("found at frame " << found_at);
    REQUIRE(found_at >= 0);
    CHECK(run.on_target());
    for (int i = found_at + 1; i < found_at + 10; ++i) {
        INFO("frame " << i);
        REQUIRE(run.step({2.0 * i, 0.0}, {40.0 - 0.5 * i, 64.0}) == TrackState::Tracking);
        CHECK(run.on_target());
    }
}

TEST_CASE("Tracker finds a target lost while the camera turned by its looks, anywhere in the frame", "[tracker][view]") {
    PanningScene run;
    const Point start{40.0, 64.0};
    REQUIRE(run.tracker.start_in({start.x - PanningScene::kA, start.y - PanningScene::kB, 2 * PanningScene::kA + 1,
                                  2 * PanningScene::kB + 1}));
    Point target = start;
    for (int i = 0; i < 15; ++i) {
        target = {start.x + 0.5 * i, start.y};
        INFO("frame " << i);
        REQUIRE(run.step({0.0, 0.0}, target) == TrackState::Tracking);
        CHECK(run.on_target());
    }
    // The camera turns (the caller says so: no differencing) while something covers the target.
    run.tracker.allow_detection(false);
    bool lost = false;
    Point pan{0.0, 0.0};
    for (int i = 0; i < 8; ++i) {
        pan.x += 4.0;
        lost = run.step(pan, target, true) != TrackState::Tracking || lost;
        CHECK(run.tracker.result().detection.passes == 0);
    }
    REQUIRE(lost);
    // The camera holds still again with the target far from where it was last seen; the caller
    // still allows no differencing, so only its looks can find it.
    const Point elsewhere{95.0, 36.0};
    int found_at = -1;
    for (int i = 0; i < 20 && found_at < 0; ++i) {
        const TrackState state = run.step(pan, elsewhere);
        CHECK(run.tracker.result().detection.passes == 0);
        if (state == TrackState::Tracking) found_at = i;
    }
    INFO("found after " << found_at << " frames");
    REQUIRE(found_at >= 0);
    CHECK(run.on_target());
    for (int i = 0; i < 5; ++i) {
        REQUIRE(run.step(pan, elsewhere) == TrackState::Tracking);
        CHECK(run.on_target());
    }
}

TEST_CASE("Tracker says how surely it finds the target's looks: sure while seen, not once hidden", "[tracker][view]") {
    // FrameResult::match_psr, the correlation filter's peak-to-sidelobe ratio where it found the
    // target: 0 on a new target's first frame (nothing learned to look for), at least 5 (the
    // filter's own "sure") while the textured target crosses the panning world, and below that, or
    // 0 with the track lost, once something hides it.
    PanningScene run;
    const Point start{40.0, 64.0};
    REQUIRE(run.tracker.start_in({start.x - PanningScene::kA, start.y - PanningScene::kB, 2 * PanningScene::kA + 1,
                                  2 * PanningScene::kB + 1}));
    REQUIRE(run.step({0.0, 0.0}, start) == TrackState::Tracking);
    CHECK(run.tracker.result().match_psr == 0.0);
    Point target = start;
    for (int i = 1; i < 12; ++i) {
        target = {start.x + 0.5 * i, start.y};
        INFO("frame " << i);
        REQUIRE(run.step({1.0 * i, 0.0}, target) == TrackState::Tracking);
        CHECK(run.on_target());
        CHECK(run.tracker.result().match_psr >= 5.0);
    }
    const TrackState hidden = run.step({12.0, 0.0}, target, true);
    INFO("hidden: " << rays::to_string(hidden) << ", psr " << run.tracker.result().match_psr);
    CHECK(run.tracker.result().match_psr < 5.0);
    if (hidden != TrackState::Tracking) CHECK(run.tracker.result().match_psr == 0.0);
}

TEST_CASE("Tracker finds a target again by its looks in the frame its contour fails the check", "[tracker][view]") {
    // The target steps away from the camera: from one frame to the next it shows at 0.69 of its
    // size, too fast a change for the attention check, and the last contour moved to where the
    // filter finds it holds much of the world round it. The target is lost, and looked for again at
    // once by its looks (attention.lost_frames = 0): it is tracking again in that same frame, which
    // reports why the track was lost.
    PanningScene run;
    const Point start{40.0, 64.0};
    REQUIRE(run.tracker.start_in({start.x - PanningScene::kA, start.y - PanningScene::kB, 2 * PanningScene::kA + 1,
                                  2 * PanningScene::kB + 1}));
    for (int i = 0; i < 25; ++i) {
        if (i == 15) run.size = 0.69;
        const Point target{start.x + 0.5 * i, start.y};
        INFO("frame " << i);
        REQUIRE(run.step({0.5 * i, 0.0}, target) == TrackState::Tracking);
        CHECK(run.on_target());
        if (i == 15) CHECK(run.tracker.result().lost_reason != nullptr);
    }
    const double shown = std::numbers::pi * 0.69 * PanningScene::kA * 0.69 * PanningScene::kB;
    CHECK(run.tracker.contour().area == Approx(shown).epsilon(0.3));
}

TEST_CASE("Tracker keeps a mover the camera follows slowly: still in the image, not in the scene", "[tracker][view]") {
    // Detection finds the target crossing a still view of a world with dark poles in it. Then the
    // camera follows it, slower than a quarter of a pixel a frame (each frame's view counts as still):
    // the target stands still in the image while the poles' edges drift, and frame differencing
    // shows them moving away from the track frame after frame. The track moves in the scene as the
    // view drifts under it: the watch on still tracks does not drop it.
    PanningScene run;
    run.poles = true;
    Point target{40.0, 64.0};
    int found_at = -1;
    for (int i = 0; i < 12 && found_at < 0; ++i) {
        target.x = 40.0 + 1.0 * i;
        if (run.step({0.0, 0.0}, target) == TrackState::Tracking) found_at = i;
    }
    REQUIRE(found_at >= 0);
    Point pan{0.0, 0.0};
    for (int i = 0; i < 80; ++i) {
        pan.x += 0.2;
        INFO("frame " << i << " of the camera following");
        REQUIRE(run.step(pan, target) == TrackState::Tracking);
        CHECK(run.tracker.result().lost_reason == nullptr);
        CHECK(run.on_target());
    }
}
