// SPDX-License-Identifier: Apache-2.0
#include "drivers/stopping_bound.hpp"

#include <algorithm>
#include <cmath>

namespace rays::ptu {
namespace {

constexpr int kBisections = 60;       // halves [0, wanted] down to far below a nanoradian per second
constexpr double kRoundingGap = 1e-10;  // rad: a plan this close to the limit counts as reaching it

// Where the axis comes to rest under the plan of fastest_stoppable, relative to where it is now.
double rest_offset(double velocity, double commanded, double hold_s, double max_accel) {
    const double ramp_s = std::min(std::abs(commanded - velocity) / max_accel, hold_s);
    const double held = ramp_s < hold_s ? commanded : velocity + std::copysign(max_accel * ramp_s, commanded - velocity);
    return 0.5 * (velocity + held) * ramp_s + held * (hold_s - ramp_s) + held * std::abs(held) / (2.0 * max_accel);
}

}  // namespace

double fastest_stoppable(double gap, double velocity, double wanted, double slew_floor, double hold_s,
                         double max_accel) {
    if (gap <= 0.0) return 0.0;  // at or beyond the limit
    if (rest_offset(velocity, wanted, hold_s, max_accel) <= gap) return wanted;
    double safe = 0.0;
    if (rest_offset(velocity, 0.0, hold_s, max_accel) > gap) {
        safe = std::clamp(velocity - max_accel * hold_s, 0.0, wanted);  // brake as hard as possible
    } else {
        double unsafe = wanted;  // the rest offset grows with the commanded velocity
        for (int i = 0; i < kBisections; ++i) {
            const double middle = 0.5 * (safe + unsafe);
            (rest_offset(velocity, middle, hold_s, max_accel) <= gap ? safe : unsafe) = middle;
        }
    }
    if (slew_floor > safe && slew_floor <= wanted &&
        rest_offset(velocity, slew_floor, hold_s, max_accel) <= gap + kRoundingGap)
        return slew_floor;
    return safe;
}

}  // namespace rays::ptu
