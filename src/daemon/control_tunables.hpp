// SPDX-License-Identifier: Apache-2.0
// The [control] and [ptu] settings as the frame loop uses them: choices parsed into enums and
// angles into radians, all trivially copyable so they cross into the loop without allocating.
#pragma once
#include "control/controller.hpp"
#include "control/lost_policy.hpp"
#include "control/target_filter.hpp"
#include "daemon/daemon_config.hpp"

namespace rays::daemon {

struct ControlTunables {
    bool predictive = true;
    control::Intrinsics intrinsics;
    control::ControllerSettings controller;  // lead_s without the unit's own latency
    control::TargetFilterSettings filter;
    control::LostSettings lost;
    double still_rad_s = 0.0;
    double coast_s = 0.0;
};

ControlTunables control_tunables(const ControlSettings& control, const PtuMotion& motion);

}  // namespace rays::daemon
