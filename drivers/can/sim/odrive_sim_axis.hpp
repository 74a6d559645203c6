// SPDX-License-Identifier: Apache-2.0
// A simulated ODrive axis on the CAN bus (CAN simple protocol, firmware v0.5 behaviour): idle or
// closed loop control, velocity (passthrough) and position (trapezoidal trajectory) control,
// heartbeat and encoder estimates sent cyclically, Clear_Errors, and the communication watchdog
// (axis.config.enable_watchdog): every message addressed to the axis feeds it; when it expires the
// axis reports WATCHDOG_TIMER_EXPIRED and goes idle. It records every frame addressed to it.
// Faults on demand: an axis error, heartbeat loss, silence. All methods thread-safe.
#pragma once
#include <cstdint>
#include <mutex>
#include <vector>

#include "drivers/axis_dynamics.hpp"
#include "drivers/can/sim/cia402_sim_drive.hpp"  // ReceivedFrame
#include "drivers/can/sim/sim_bus_host.hpp"

namespace rays::odrive {

struct OdriveSimConfig {
    int node = 0;
    double turns_per_rad = 1.0 / 6.283185307179586;
    ptu::AxisDynamicsConfig dynamics{3.0, 20.0, 0.0};
    int heartbeat_ms = 20;
    int encoder_ms = 5;
    bool enable_watchdog = true;
    double watchdog_timeout_s = 0.1;
    std::size_t record_capacity = 1 << 16;
};

class OdriveSimAxis final : public can::SimNode {
public:
    explicit OdriveSimAxis(const OdriveSimConfig& config);

    void on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus) override;
    void tick(TimePoint now, can::FrameSink& bus) override;

    double position_rad() const;
    double velocity_rad_s() const;
    std::uint32_t axis_state() const;
    std::uint32_t axis_error() const;
    std::vector<canopen::ReceivedFrame> received() const;

    void inject_error(std::uint32_t error);  // stays until clear_fault, then Clear_Errors clears it
    void clear_fault();
    void stop_heartbeat(bool stopped);
    void mute(bool muted);

private:
    void go_idle(TimePoint now);

    mutable std::mutex mutex_;
    const OdriveSimConfig config_;
    ptu::AxisDynamics axis_;
    std::vector<canopen::ReceivedFrame> received_;
    std::uint32_t state_ = 1, error_ = 0, control_mode_ = 2, input_mode_ = 1;
    bool fault_condition_ = false, heartbeat_stopped_ = false, muted_ = false;
    TimePoint next_heartbeat_{}, next_encoder_{}, last_feed_{};
    bool fed_ = false;
};

}  // namespace rays::odrive
