// SPDX-License-Identifier: Apache-2.0
// The watch on still tracks. Frame differencing may start a track on the background beside the
// moving object (the part it just uncovered, or a patch that looks alike), and a track may slide off
// a mover onto background that looks alike and stay there while the mover walks on. Such a track
// stands still in the scene. While a track does and the view stands still too (as the frames show
// it: a unit's small corrections do not move it), the motion detector goes on looking: motion found
// away from the contour frame after frame (and more often than in it) means the track is not on the
// mover. Not while the view turns: that moves everything. The tracker asks the detector and drops
// the track; this class keeps the count. Fixed size; nothing allocated.
#pragma once

#include "core/contour.hpp"
#include "core/motion_detector.hpp"
#include "core/view_motion.hpp"

namespace rays {

class StillTrackWatch {
public:
    // A new track, or none: it has not stood anywhere yet.
    void restart() { still_frames_ = -1; }

    // This frame's contour centroid `at` and the view's motion since the previous frame: true when
    // the track has stood still in the scene (not merely in the image: a mover the unit follows
    // stands still in the image while the view drifts under it) long enough, on a still view, that
    // the detector is to be asked where the motion is (on the previous frame aligned by the view's
    // `drift`: a still view's drift too moves a strong edge enough to show).
    bool stands_still(Point at, const ViewShift& view);

    // The detector's answer for this frame (`stands_still` was true): false when motion has been
    // found away from `contour` often enough, and more often than in it, that the track is not on
    // the mover. Motion counts as in it where the detector's mover is, or where any other region it
    // found is: a slow target's own motion, which a bigger mover elsewhere outweighs.
    bool on_mover(const Detection& detection, const Contour& contour, const MotionDetector& detector);

private:
    int still_frames_ = -1;   // frames the track has stood still in the scene near still_at_ (-1: a new track)
    Point still_at_;          // where it stands
    Point view_drift_;        // how far the view has moved since it stood there
    int motion_inside_ = 0;   // of this window's still frames, those whose motion was found in the contour
    int motion_outside_ = 0;  // ... and away from it
};

}  // namespace rays
