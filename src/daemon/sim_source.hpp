// SPDX-License-Identifier: Apache-2.0
// The simulated pan/tilt camera as a frame source of raysd, beside V4L2 and replay: each frame is
// rendered (src/sim) at the unit's angles as the configured driver last reported them to the frame
// loop — mock or real — extrapolated at their rate to the capture time, so the loop closes through
// the simulation exactly as through a camera on a rig. Paced in real time at sim.fps; a live source.
// The rig's pan/tilt zero faces the scenario's start.
#pragma once
#include <atomic>
#include <memory>
#include <string>

#include "core/clock.hpp"
#include "daemon/daemon_config.hpp"
#include "daemon/frame_source.hpp"
#include "daemon/loop_channels.hpp"
#include "sim/exposure_delay.hpp"
#include "sim/sim_camera.hpp"

namespace rays::daemon {

// The simulated camera [sim] describes, seeing through the intrinsics [control] gives the
// controller; null with `error` for an unknown scenario or an unreadable panorama.
std::unique_ptr<sim::SimCamera> make_sim_camera(const DaemonConfig& config, std::string& error);

class SimSource final : public FrameSource {
public:
    // Null with `error` as make_sim_camera.
    static std::unique_ptr<SimSource> open(const DaemonConfig& config, const Clock& clock, std::string& error);

    // Where the unit's angles come from: the frame loop's published status. Until then the unit is
    // taken to rest at zero.
    void follow(const LoopChannels& channels) { channels_.store(&channels); }

    Result next(CapturedFrame& out, std::chrono::milliseconds timeout) override;
    bool live() const override { return true; }
    std::string describe() const override;

private:
    SimSource(const SimSettings& settings, std::unique_ptr<sim::SimCamera> camera, const Clock& clock);
    void unit_angles(TimePoint at, double& pan, double& tilt) const;

    SimSettings settings_;
    std::unique_ptr<sim::SimCamera> camera_;
    std::unique_ptr<sim::SimView> view_;
    const Clock& clock_;
    std::atomic<const LoopChannels*> channels_{nullptr};
    TimePoint start_{};
    long delivered_ = 0;
    sim::ExposureDelay delay_;  // sim.latency_frames
};

}  // namespace rays::daemon
