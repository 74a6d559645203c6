// SPDX-License-Identifier: Apache-2.0
// raysd's one process, wired from its config: frame source (capture thread) → frame loop thread
// (tracker, controller, limited PTU driver) and the socket thread (requests, watch, signals), plus
// sd_notify. Config errors are found before anything starts; the PTU is stopped on every way out.
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "daemon/daemon_config.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/frame_source.hpp"
#include "drivers/calibrated_ptu.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::daemon {

// The unit's per-axis inversion and zero offset as [ptu] gives them.
std::array<ptu::AxisCalibration, ptu::kAxes> calibration_of(const PtuSettings& ptu);

struct DaemonParts {
    std::unique_ptr<FrameSource> source;  // null: from [camera]
    std::unique_ptr<ptu::PtuDriver> ptu;  // null: from [ptu]
    FrameObserver* observer = nullptr;    // tests: sees every processed frame
};

// Blocks SIGHUP, SIGTERM, SIGINT (taken through a signalfd) and ignores SIGPIPE, in the calling
// thread and every thread started after; call before any thread starts.
void block_daemon_signals();

// The frame source [camera] (and for the simulated camera [sim]) describes; null with `error` when it cannot be opened.
std::unique_ptr<FrameSource> open_frame_source(const DaemonConfig& config, const Clock& clock, std::string& error);

// Runs until SIGTERM/SIGINT (or request_stop() from another thread). Returns the exit status:
// 0 after a clean stop, 78 (EX_CONFIG) when the configured PTU driver cannot be made from its section
// (as --check-config reports it), 1 when the camera, PTU or socket cannot be brought up.
class Daemon {
public:
    Daemon(DaemonConfig config, std::string config_path, DaemonParts parts, const Clock& clock);
    ~Daemon();
    int run();
    void request_stop();

private:
    struct Running;
    DaemonConfig config_;
    std::string config_path_;
    DaemonParts parts_;
    const Clock& clock_;
    std::unique_ptr<Running> running_;
};

}  // namespace rays::daemon
