// SPDX-License-Identifier: Apache-2.0
// Smooth target paths for the scenes, evaluated at any frame (random access).
#pragma once
#include "core/image.hpp"

namespace rays::scenes {

// An elliptical loop around (cx, cy) with semi-axes a (along `tilt`) and b, travelled at `rate`
// rad/frame from the angle `start`: the speed stays between b·rate and a·rate px/frame.
struct Loop {
    double cx, cy, a, b, tilt, rate, start;
    Point at(double frame) const;
    double heading(double frame) const;  // direction of motion, rad
};

// Position on a back-and-forth run between lo and hi after travelling `distance` from lo.
double bounce(double lo, double hi, double distance);

// Distance travelled by frame t of the speed-ramp scene: 2 → 8 px/frame over frames 0–169, a steady
// 8 px/frame over frames 170–229, then 8 → 16 px/frame by frame 399.
double ramp_distance(int t);

}  // namespace rays::scenes
