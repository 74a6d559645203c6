// SPDX-License-Identifier: Apache-2.0
// The fastest velocity an axis may be commanded toward a limit and still stop before it, given
// that the command is held until the next one arrives. Pure arithmetic, for PtuLimiter.
#pragma once

namespace rays::ptu {

// The velocity in [0, wanted] to command an axis `gap` away from a limit, now moving at `velocity`
// (positive: toward the limit). A command v is safe when ramping at max_accel to v, holding it until
// hold_s from now and then braking at max_accel brings the axis to rest at most `gap` ahead.
// Returns wanted when safe, else the fastest safe command, and 0 when gap ≤ 0. When no command is
// safe, the axis is already past its braking point: returns the fastest command that still brakes
// it at max_accel throughout hold_s. `slew_floor` (the least the slew limit allows) is returned
// instead of anything smaller when it misses by no more than rounding.
double fastest_stoppable(double gap, double velocity, double wanted, double slew_floor, double hold_s,
                         double max_accel);

}  // namespace rays::ptu
