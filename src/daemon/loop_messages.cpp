// SPDX-License-Identifier: Apache-2.0
#include "daemon/loop_messages.hpp"

namespace rays::daemon {

LoopTunables loop_tunables(const DaemonConfig& config) {
    LoopTunables tunables;
    tunables.tracker = config.tracker.tunables;
    tunables.budget_ms = config.loop.budget_ms;
    tunables.control = control_tunables(config.control, config.ptu.motion);
    tunables.ptu = config.ptu.motion;
    return tunables;
}

const char* to_string(ControlMode mode) { return mode == ControlMode::Automatic ? "automatic" : "manual"; }

}  // namespace rays::daemon
