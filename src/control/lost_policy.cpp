// SPDX-License-Identifier: Apache-2.0
#include "control/lost_policy.hpp"

#include <cmath>

namespace rays::control {
namespace {

ptu::PtuCommand go_to(double pan, double tilt) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Position, pan};
    command.axes[1] = {ptu::CommandMode::Position, tilt};
    return command;
}

}  // namespace

void LostPolicy::lost_at(double t_s, double pan_rad, double tilt_rad) {
    lost_s_ = t_s;
    pan_ = pan_rad;
    tilt_ = tilt_rad;
    go_back_ = false;
}

void LostPolicy::lost_after_coasting(double t_s, double pan_rad, double tilt_rad) {
    lost_at(t_s, pan_rad, tilt_rad);
    go_back_ = true;
}

ptu::PtuCommand LostPolicy::command(double t_s) const {
    const double waited = t_s - lost_s_ - settings_.timeout_s;
    if (waited < 0 || settings_.action == LostAction::Hold) return go_back_ ? go_to(pan_, tilt_) : ptu::PtuCommand::stop();
    if (settings_.action == LostAction::Home) return go_to(settings_.home_pan_rad, settings_.home_tilt_rad);
    // Search poses: 0, +1, −1, +2, −2, … steps from where the target was lost, then round again.
    const int poses = 2 * settings_.search_steps + 1;
    const auto k = static_cast<int>(std::fmod(std::floor(waited / settings_.search_dwell_s), poses));
    const int side = (k + 1) / 2;
    const double offset = (k % 2 == 1 ? side : -side) * settings_.search_step_rad;
    return go_to(pan_ + offset, tilt_);
}

}  // namespace rays::control
