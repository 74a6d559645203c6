// SPDX-License-Identifier: Apache-2.0
// What the unit does while no target is tracked: hold still (so frame differencing can find the
// target again) — where the target was last seen, when a prediction followed after it led nowhere —
// and after a timeout either keep holding, search — stepping the pan axis through
// poses left and right of where the target was lost, dwelling at each so detection can run — or
// return to the home pose.
#pragma once
#include "drivers/ptu_driver.hpp"

namespace rays::control {

enum class LostAction { Hold, Search, Home };

struct LostSettings {
    LostAction action = LostAction::Hold;
    double timeout_s = 3.0;          // holding still this long before searching or going home
    double search_step_rad = 0.35;   // pan step between search poses
    int search_steps = 3;            // poses on each side of where the target was lost
    double search_dwell_s = 1.5;     // time at each search pose (moving there included)
    double home_pan_rad = 0;
    double home_tilt_rad = 0;
};

class LostPolicy {
public:
    void set_settings(const LostSettings& settings) { settings_ = settings; }
    // The target was lost at t_s with the unit at (pan, tilt): it holds still there.
    void lost_at(double t_s, double pan_rad, double tilt_rad);
    // The target was lost at t_s after the unit had followed its prediction without finding it
    // again: the unit goes back to (pan, tilt), where it was last seen, and holds still there.
    void lost_after_coasting(double t_s, double pan_rad, double tilt_rad);
    // The command t_s seconds on the loop's clock: zero velocity, or a position command.
    ptu::PtuCommand command(double t_s) const;

private:
    LostSettings settings_;
    double lost_s_ = 0;
    double pan_ = 0, tilt_ = 0;
    bool go_back_ = false;  // holding means going back to (pan_, tilt_), not stopping where it is
};

}  // namespace rays::control
