// SPDX-License-Identifier: Apache-2.0
#include "core/still_track_watch.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {
namespace {

constexpr double kStillRadiusPx = 6.0;   // a track whose centroid stays this near one point ...
constexpr int kStillFrames = 8;          // ... this many frames stands still (slower than 0.75 px/frame);
constexpr int kWatchWindowFrames = 20;   // while it does, the motion found in and away from it is counted
constexpr int kMotionAwayFrames = 5;     // per this many frames: this often away (and twice as often as in
                                         // it), and the track is not on the mover

}  // namespace

bool StillTrackWatch::stands_still(Point at, const ViewShift& view) {
    if (view.known) view_drift_ = {view_drift_.x + view.drift.x, view_drift_.y + view.drift.y};
    if (still_frames_ < 0 ||
        std::hypot(at.x - still_at_.x - view_drift_.x, at.y - still_at_.y - view_drift_.y) >= kStillRadiusPx) {
        still_at_ = at;
        view_drift_ = {};
        still_frames_ = 0;
        motion_inside_ = motion_outside_ = 0;
        return false;
    }
    if (++still_frames_ % kWatchWindowFrames == 0) motion_inside_ = motion_outside_ = 0;
    return still_frames_ >= kStillFrames && view.still;
}

bool StillTrackWatch::on_mover(const Detection& detection, const Contour& contour, const MotionDetector& detector) {
    if (!detection.found) return true;
    // In it: inside the contour, or as near its centroid as its equivalent radius (a faint mover's
    // difference may show only where it was, just behind its rim).
    const Point c = contour.centroid;
    const double reach = std::sqrt(std::max(contour.area, 0.0) / std::numbers::pi);
    auto in_track = [&](Point p) { return contour_contains(contour, p) || std::hypot(p.x - c.x, p.y - c.y) <= reach; };
    if (in_track(detection.centre) || detector.any_region(in_track)) {
        ++motion_inside_;
        return true;
    }
    ++motion_outside_;
    return motion_outside_ < kMotionAwayFrames || motion_outside_ <= 2 * motion_inside_;
}

}  // namespace rays
