// SPDX-License-Identifier: Apache-2.0
// One CiA 402 drive as raysd runs it, on the driver's I/O thread: bring-up by SDO (configuration
// plan), NMT start, the controlword/statusword state machine to Operation enabled, targets by RPDO,
// actual values by TPDO, its heartbeat watched, faults reset and the bring-up retried with backoff
// (0.5 s doubling to 8 s) until the drive answers again. No allocation after construction.
#pragma once
#include <cstdint>

#include "core/clock.hpp"
#include "drivers/can/can_transport.hpp"
#include "drivers/can/canopen/cia402.hpp"
#include "drivers/can/canopen/configuration_plan.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::canopen {

class CanopenAxis {
public:
    CanopenAxis(const char* label, int node, double counts_per_rad, const CanopenSettings& settings);

    void start(TimePoint now);  // from scratch: pre-operational, then the configuration plan
    void forget_faults();       // a new session (configure): earlier failures no longer count
    bool on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus);  // false: not this drive's frame
    void lose(const char* why, TimePoint now);            // a fault from outside (bus-off): retry later
    // `enable`: bring the drive to Operation enabled and apply `command` (a stop otherwise).
    void cycle(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus);
    void stop(can::FrameSink& bus);  // quick stop, then pre-operational

    bool configured() const { return phase_ == Phase::Configured || phase_ == Phase::Operational; }
    bool enabled() const { return phase_ == Phase::Operational && state_ == DriveState::OperationEnabled && !faulted(); }
    bool faulted() const { return !status_.ok; }
    ptu::AxisState state() const;
    TimePoint stamp() const { return stamp_; }
    const ptu::DriverStatus& status() const { return status_; }

private:
    enum class Phase { Configuring, Backoff, Configured, Operational };

    void send_sdo(TimePoint now, can::FrameSink& bus);
    void on_sdo_reply(const can_frame& frame, TimePoint now, can::FrameSink& bus);
    void fail(TimePoint now, const char* format, ...) __attribute__((format(printf, 3, 4)));
    void send_rpdo(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus);
    std::uint16_t position_handshake(std::int32_t target, std::int32_t& send);
    std::int32_t to_counts(double value) const;
    bool drive_fault_ = false;

    const char* label_;
    const int node_;
    const double counts_per_rad_;
    const ConfigurationPlan plan_;
    const TimePoint::duration sdo_timeout_, heartbeat_timeout_;
    const bool absolute_;

    Phase phase_ = Phase::Backoff;
    std::size_t step_ = 0;
    bool sdo_pending_ = false;
    bool nmt_pending_ = false;  // NMT enter pre-operational still to send
    TimePoint sdo_deadline_{}, retry_at_{}, last_heartbeat_{};
    double backoff_s_ = 0.5;
    ptu::DriverStatus status_;

    std::uint16_t statusword_ = 0;
    DriveState state_ = DriveState::NotReadyToSwitchOn;
    std::int32_t position_counts_ = 0, velocity_counts_ = 0;
    TimePoint stamp_{};
    std::uint16_t last_emcy_ = 0;
    // Fault reset: bit 7 rises once per backoff interval (CiA 402-2 §6.1, transition 15).
    std::uint16_t last_controlword_ = 0;
    TimePoint next_reset_{};
    // Profile position handshake (new set-point bit 4 ↔ set-point acknowledge bit 12).
    bool setpoint_requested_ = false, setpoint_valid_ = false;
    std::int32_t setpoint_sent_ = 0, setpoint_acked_ = 0;
};

}  // namespace rays::canopen
