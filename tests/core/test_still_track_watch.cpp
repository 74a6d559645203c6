// SPDX-License-Identifier: Apache-2.0
// The watch on still tracks: when a track counts as standing still in the scene, and when the motion
// the detector finds away from it means it is not on the mover.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "core/still_track_watch.hpp"

namespace {

using rays::Contour;
using rays::Detection;
using rays::Point;
using rays::StillTrackWatch;
using rays::ViewShift;

constexpr Point kAt{64.0, 64.0};

// A disc of radius 8 round kAt, as a contour of 32 points.
Contour disc() {
    Contour c{rays::TrackerCapacity{}};
    c.size = 32;
    for (int k = 0; k < c.size; ++k) {
        const double a = 2.0 * std::numbers::pi * k / c.size;
        c.points[k].p = {kAt.x + 8.0 * std::cos(a), kAt.y + 8.0 * std::sin(a)};
    }
    c.area = std::numbers::pi * 64.0;
    c.centroid = kAt;
    c.ref = kAt;
    return c;
}

ViewShift still_view() {
    ViewShift v;
    v.known = true;
    v.still = true;
    return v;
}

Detection motion_at(Point p) {
    Detection d;
    d.found = true;
    d.centre = p;
    return d;
}

// A detector that has found nothing: the motion is the Detection a test gives, and nothing else.
const rays::MotionDetector kNothingElse;

// Frames until the watch first asks the detector, for a track held at `at` on `view` (0: never in 40).
int frames_until_asked(StillTrackWatch& watch, Point at, const ViewShift& view) {
    for (int frame = 1; frame <= 40; ++frame)
        if (watch.stands_still(at, view)) return frame;
    return 0;
}

}  // namespace

TEST_CASE("StillTrackWatch: a track still on a still view is watched from its ninth frame", "[still_watch]") {
    StillTrackWatch watch;
    CHECK(frames_until_asked(watch, kAt, still_view()) == 9);  // where it stands, then 8 frames still
}

TEST_CASE("StillTrackWatch: motion away from a still track five times, and not in it, drops it", "[still_watch]") {
    StillTrackWatch watch;
    const Contour contour = disc();
    REQUIRE(frames_until_asked(watch, kAt, still_view()) == 9);
    for (int k = 1; k < 5; ++k) {
        CHECK(watch.on_mover(motion_at({110.0, 20.0}), contour, kNothingElse));
        REQUIRE(watch.stands_still(kAt, still_view()));
    }
    CHECK_FALSE(watch.on_mover(motion_at({110.0, 20.0}), contour, kNothingElse));
}

TEST_CASE("StillTrackWatch: motion in the track as often as away keeps it", "[still_watch]") {
    StillTrackWatch watch;
    const Contour contour = disc();
    REQUIRE(frames_until_asked(watch, kAt, still_view()) == 9);
    // Motion found in the contour three times ...
    for (int k = 0; k < 3; ++k) {
        CHECK(watch.on_mover(motion_at({kAt.x + 3.0, kAt.y}), contour, kNothingElse));
        REQUIRE(watch.stands_still(kAt, still_view()));
    }
    for (int k = 0; k < 6; ++k) {
        CHECK(watch.on_mover(motion_at({110.0, 20.0}), contour, kNothingElse));  // 6 away ≤ twice 3 in it
        REQUIRE(watch.stands_still(kAt, still_view()));
    }
    CHECK_FALSE(watch.on_mover(motion_at({110.0, 20.0}), contour, kNothingElse));  // 7 away > twice 3
    CHECK(watch.on_mover(Detection{}, contour, kNothingElse));  // no motion found: no evidence either way
}

TEST_CASE("StillTrackWatch: no watch while the view moves, or once the track moves on", "[still_watch]") {
    StillTrackWatch moving_view;
    ViewShift turning;
    turning.known = true;
    turning.shift = {2.0, 0.0};
    turning.drift = {0.0, 0.0};  // the track moves with the view: still in the scene, but the view is not
    CHECK(frames_until_asked(moving_view, kAt, turning) == 0);

    StillTrackWatch moved_on;
    REQUIRE(frames_until_asked(moved_on, kAt, still_view()) == 9);
    CHECK_FALSE(moved_on.stands_still({kAt.x + 7.0, kAt.y}, still_view()));  // 7 px on: stands somewhere new
    CHECK(frames_until_asked(moved_on, {kAt.x + 7.0, kAt.y}, still_view()) == 8);

    StillTrackWatch restarted;
    REQUIRE(frames_until_asked(restarted, kAt, still_view()) == 9);
    restarted.restart();
    CHECK(frames_until_asked(restarted, kAt, still_view()) == 9);
}

TEST_CASE("StillTrackWatch: a track held still in the image while the view drifts under it moves in the scene",
          "[still_watch]") {
    // A slow pan: each frame measures as still, but the view drifts 1 px a frame; a mover the unit
    // follows stays where it is in the image, so in the scene it moves 1 px a frame.
    ViewShift drifting = still_view();
    drifting.drift = {1.0, 0.0};
    StillTrackWatch watch;
    CHECK(frames_until_asked(watch, kAt, drifting) == 0);
    // Background still in the scene moves with the drift in the image: that track is still.
    StillTrackWatch on_background;
    bool asked = false;
    Point at = kAt;
    for (int frame = 1; frame <= 9; ++frame) {
        asked = on_background.stands_still(at, drifting);
        at.x += 1.0;
    }
    CHECK(asked);
}

TEST_CASE("StillTrackWatch: a slow mover's own motion in the track keeps it, though a bigger mover away is the detection",
          "[still_watch]") {
    // The track stands at kAt, as a slow mover's does, on a small disc whose rim moves 1 px a frame;
    // a bigger disc far away moves 4 px a frame, and the detector's detection is the bigger one.
    auto frame = [](int k) {
        rays::GreyImage image;
        image.px.fill(20);
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                if (std::hypot(x - (kAt.x + k), y - kAt.y) <= 7.0) image.at(x, y) = 120;
                if (std::hypot(x - (20.0 + 4 * k), y - 20.0) <= 14.0) image.at(x, y) = 200;
            }
        return image;
    };
    rays::MotionDetector detector;
    StillTrackWatch watch;
    const Contour contour = disc();
    REQUIRE(frames_until_asked(watch, kAt, still_view()) == 9);
    for (int k = 1; k <= 8; ++k) {
        const Detection d = detector.detect(frame(k - 1), frame(k), rays::DetectTunables{});
        REQUIRE(d.found);
        REQUIRE(std::hypot(d.centre.x - kAt.x, d.centre.y - kAt.y) > 30.0);  // the bigger mover, away
        CHECK(watch.on_mover(d, contour, detector));
        REQUIRE(watch.stands_still(kAt, still_view()));
    }
    // The same detections without the small disc's own motion drop the track at the fifth.
    StillTrackWatch without;
    REQUIRE(frames_until_asked(without, kAt, still_view()) == 9);
    int dropped_at = 0;
    for (int k = 1; k <= 8 && dropped_at == 0; ++k) {
        const Detection d = detector.detect(frame(k - 1), frame(k), rays::DetectTunables{});
        if (!without.on_mover(d, contour, kNothingElse)) dropped_at = k;
        REQUIRE(without.stands_still(kAt, still_view()));
    }
    CHECK(dropped_at == 5);
}
