// One closed-loop run as on a rig, headless: the simulated camera renders each frame at the mock
// unit's actual angles, raysd's own FrameLoop tracks and steers (controller, PtuLimiter,
// CalibratedPtu, MockPtu with its dynamics), and every frame's ground truth is recorded.
#pragma once
#include <string>
#include <vector>

#include "daemon/daemon_config.hpp"
#include "soak_metrics.hpp"

namespace rays::soak {

struct SoakRun {
    daemon::DaemonConfig config;  // tracker, control, ptu limits, mock dynamics, sim scenario/seed/fps
    long frames = 45000;
};

// The frames' records; empty with `error` set when the run could not start.
std::vector<SoakFrame> run_closed_loop(const SoakRun& run, std::string& error);

}  // namespace rays::soak
