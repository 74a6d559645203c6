// SPDX-License-Identifier: Apache-2.0
// A CANopen driver on an in-memory bus with two simulated CiA 402 drives (pan node 1, tilt node 2),
// with short timings so that faults show within a fraction of a second.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "drivers/can/canopen/canopen_driver.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"
#include "drivers/can/sim/cia402_sim_drive.hpp"
#include "drivers/can/sim/loopback_bus.hpp"
#include "support/eventually.hpp"

namespace rays::test {

inline canopen::CanopenSettings fast_canopen_settings() {
    canopen::CanopenSettings s;
    s.master_heartbeat_ms = 20;
    s.drive_consumer_timeout_ms = 100;
    s.drive_heartbeat_ms = 20;
    s.drive_heartbeat_timeout_ms = 100;
    s.tpdo_period_ms = 5;
    s.cycle_ms = 5;
    s.sdo_timeout_ms = 50;
    s.command_timeout_s = 0.3;
    s.lifecycle_timeout_s = 2.0;
    return s;
}

inline canopen::Cia402SimConfig sim_config(int node, const canopen::CanopenSettings& s, int counts_per_turn) {
    canopen::Cia402SimConfig config;
    config.node = node;
    config.counts_per_rad = counts_per_turn / (2.0 * 3.141592653589793);
    (void)s;
    return config;
}

struct CanopenRig {
    explicit CanopenRig(const canopen::CanopenSettings& s = fast_canopen_settings())
        : settings(s),
          pan(sim_config(s.pan_node_id, s, s.pan_counts_per_turn)),
          tilt(sim_config(s.tilt_node_id, s, s.tilt_counts_per_turn)),
          host(bus, {&pan, &tilt}),
          driver_end(bus.add_endpoint()) {
        std::string error;
        driver = canopen::make_canopen_driver(settings, bus.transport_for(driver_end), clock, error);
    }

    // Writes `command` and reads every 5 ms for `seconds`; true when every read was ok.
    bool run(const ptu::PtuCommand& command, double seconds) {
        bool all_ok = true;
        const auto end = MonoClock::now() + std::chrono::duration<double>(seconds);
        while (MonoClock::now() < end) {
            all_ok = driver->write(command, clock.now()).ok && all_ok;
            all_ok = driver->read(state, clock.now()).ok && all_ok;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return all_ok;
    }

    // Writes `command` every 5 ms until `done`, for at most kEventTimeout; true when done.
    bool run_until(const ptu::PtuCommand& command, const std::function<bool()>& done) {
        const auto end = MonoClock::now() + kEventTimeout;
        while (MonoClock::now() < end) {
            status = driver->write(command, clock.now());
            status = driver->read(state, clock.now());
            if (done()) return true;
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return false;
    }

    canopen::CanopenSettings settings;
    SteadyClock clock;
    can::LoopbackBus bus{clock};
    canopen::Cia402SimDrive pan, tilt;
    can::SimBusHost host;
    can::LoopbackEndpoint& driver_end;
    std::unique_ptr<ptu::PtuDriver> driver;
    ptu::PtuState state;
    ptu::DriverStatus status;
};

inline ptu::PtuCommand velocities(double pan, double tilt) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Velocity, pan};
    command.axes[1] = {ptu::CommandMode::Velocity, tilt};
    return command;
}

inline ptu::PtuCommand positions(double pan, double tilt) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Position, pan};
    command.axes[1] = {ptu::CommandMode::Position, tilt};
    return command;
}

// Moves a rig's pan axis (a CanopenRig or an OdriveRig) to `pan` by position commands: the fastest the
// simulated axis went on the way, rad/s; none when it did not arrive.
template <typename Rig>
std::optional<double> fastest_pan_move(Rig& rig, double pan) {
    double fastest = 0.0;
    const bool arrived = rig.run_until(positions(pan, 0.0), [&] {
        fastest = std::max(fastest, std::abs(rig.pan.velocity_rad_s()));
        return std::abs(rig.pan.position_rad() - pan) < 1e-3;
    });
    return arrived ? std::optional<double>(fastest) : std::nullopt;
}

// Frames the drive received with this COB-ID.
inline std::vector<canopen::ReceivedFrame> frames_with_id(const canopen::Cia402SimDrive& drive, std::uint32_t id) {
    std::vector<canopen::ReceivedFrame> out;
    for (const auto& r : drive.received())
        if ((r.frame.can_id & CAN_SFF_MASK) == id && (r.frame.can_id & CAN_ERR_FLAG) == 0) out.push_back(r);
    return out;
}

// Whether the drive received an SDO download of `value` to index:sub.
inline bool received_sdo_write(const canopen::Cia402SimDrive& drive, int node, std::uint16_t index, std::uint8_t sub,
                               std::uint32_t value) {
    for (const auto& r : frames_with_id(drive, canopen::sdo_rx_id(node))) {
        const can_frame& f = r.frame;
        const std::uint32_t v = f.data[4] | (f.data[5] << 8) | (f.data[6] << 16) | (static_cast<std::uint32_t>(f.data[7]) << 24);
        if ((f.data[0] & 0xE0) == 0x20 && (f.data[1] | (f.data[2] << 8)) == index && f.data[3] == sub && v == value)
            return true;
    }
    return false;
}

}  // namespace rays::test
