// SPDX-License-Identifier: Apache-2.0
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
    bool start_at_truth = true;  // the first frame's true target centre is given as a start point (as
                                 // `raysctl track X Y` would); false: the tracker detects it by itself
    bool lockstep = false;    // time stands still within a frame (SoakClock): the same run every time
    std::string overlay_dir;  // when set, frames within the window are written there as PNG
    double overlay_from_s = 0, overlay_to_s = 0;
};

// The frames' records; empty with `error` set when the run could not start.
std::vector<SoakFrame> run_closed_loop(const SoakRun& run, std::string& error);

}  // namespace rays::soak
