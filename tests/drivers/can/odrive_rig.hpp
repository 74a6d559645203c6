// SPDX-License-Identifier: Apache-2.0
// An ODrive driver on an in-memory bus with two simulated ODrive axes (pan node 0, tilt node 1).
#pragma once
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>

#include "drivers/can/odrive/odrive_driver.hpp"
#include "drivers/can/odrive/odrive_protocol.hpp"
#include "drivers/can/sim/loopback_bus.hpp"
#include "drivers/can/sim/odrive_sim_axis.hpp"
#include "support/eventually.hpp"

namespace rays::test {

inline odrive::OdriveSettings fast_odrive_settings() {
    odrive::OdriveSettings s;
    s.pan_motor_turns_per_axis_turn = 10.0;
    s.tilt_motor_turns_per_axis_turn = 5.0;
    s.heartbeat_timeout_ms = 100;
    s.cycle_ms = 5;
    s.command_timeout_s = 0.3;
    s.lifecycle_timeout_s = 2.0;
    return s;
}

inline odrive::OdriveSimConfig odrive_sim_config(int node, double ratio, double watchdog_timeout_s = 0.1) {
    odrive::OdriveSimConfig config;
    config.watchdog_timeout_s = watchdog_timeout_s;
    config.node = node;
    config.turns_per_rad = ratio / (2.0 * 3.141592653589793);
    return config;
}

// tilt_silent: the tilt axis never sends a frame, muted before the host's thread starts (muting it
// afterwards races with the first heartbeat, which the driver would then have seen).
struct OdriveRig {
    explicit OdriveRig(const odrive::OdriveSettings& s = fast_odrive_settings(), double watchdog_timeout_s = 0.1,
                       bool tilt_silent = false)
        : settings(s),
          pan(odrive_sim_config(s.pan_node_id, s.pan_motor_turns_per_axis_turn, watchdog_timeout_s)),
          tilt(odrive_sim_config(s.tilt_node_id, s.tilt_motor_turns_per_axis_turn, watchdog_timeout_s)),
          host(bus, {&pan, &muted_if(tilt, tilt_silent)}),
          driver_end(bus.add_endpoint()) {
        std::string error;
        driver = odrive::make_odrive_driver(settings, bus.transport_for(driver_end), clock, error);
    }

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

    static odrive::OdriveSimAxis& muted_if(odrive::OdriveSimAxis& axis, bool silent) {
        if (silent) axis.mute(true);
        return axis;
    }

    odrive::OdriveSettings settings;
    SteadyClock clock;
    can::LoopbackBus bus{clock};
    odrive::OdriveSimAxis pan, tilt;
    can::SimBusHost host;
    can::LoopbackEndpoint& driver_end;
    std::unique_ptr<ptu::PtuDriver> driver;
    ptu::PtuState state;
    ptu::DriverStatus status;
};

// Commands (cmd ids) the simulated axis received, in order.
inline std::vector<odrive::Cmd> commands_received(const odrive::OdriveSimAxis& axis) {
    std::vector<odrive::Cmd> out;
    for (const auto& r : axis.received()) out.push_back(odrive::cmd_of(r.frame.can_id & CAN_SFF_MASK));
    return out;
}

}  // namespace rays::test
