// SPDX-License-Identifier: Apache-2.0
// The CANopen driver against two simulated CiA 402 drives on the in-memory bus. Every check on
// what the unit did reads the simulated drives (their received frames and their motion), not the
// driver's own account.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "canopen_rig.hpp"
#include "drivers/can/canopen/canopen_settings.hpp"

using namespace rays;
using namespace rays::canopen;
using rays::test::CanopenRig;
using rays::test::frames_with_id;
using rays::test::positions;
using rays::test::received_sdo_write;
using rays::test::velocities;

namespace {

bool contains(const ptu::DriverStatus& status, const char* text) { return std::strstr(status.what(), text) != nullptr; }

void bring_up(CanopenRig& rig) {
    REQUIRE(rig.driver != nullptr);
    const ptu::DriverStatus configured = rig.driver->configure();
    INFO(configured.what());
    REQUIRE(configured.ok);
    const ptu::DriverStatus activated = rig.driver->activate();
    INFO(activated.what());
    REQUIRE(activated.ok);
}

}  // namespace

TEST_CASE("canopen: bring-up configures each drive by SDO and enables it through the state machine", "[canopen]") {
    CanopenRig rig;
    REQUIRE(rig.driver != nullptr);
    REQUIRE(rig.driver->configure().ok);
    // What the pan drive received and now holds in its object dictionary.
    const int node = rig.settings.pan_node_id;
    CHECK(received_sdo_write(rig.pan, node, od::kControlword, 0, cw::kQuickStop));
    CHECK(rig.pan.object(od::kConsumerHeartbeat, 1) == ((127u << 16) | 100u));  // watches raysd's heartbeat
    CHECK(rig.pan.object(od::kProducerHeartbeat, 0) == 20u);
    CHECK(rig.pan.object(od::kAbortConnection, 0) == static_cast<std::uint32_t>(kAbortQuickStop));
    CHECK(rig.pan.object(od::kModesOfOperation, 0) == static_cast<std::uint32_t>(kProfileVelocity));
    CHECK(rig.pan.object(od::kMaxProfileVelocity, 0) > 0u);
    CHECK(rig.pan.object(od::kProfileAcceleration, 0) > 0u);
    CHECK(rig.pan.object(od::kRpdoMap, 0) == 3u);
    CHECK(rig.pan.object(od::kRpdoMap, 3) == mapping(od::kTargetVelocity, 0, 32));
    CHECK(rig.pan.object(od::kRpdoMap + 1, 3) == mapping(od::kTargetPosition, 0, 32));
    CHECK(rig.pan.object(od::kTpdoMap, 2) == mapping(od::kPositionActual, 0, 32));
    CHECK(rig.pan.object(od::kTpdoMap + 1, 1) == mapping(od::kVelocityActual, 0, 32));
    CHECK(rig.pan.object(od::kTpdoComm, 1) == tpdo_id(1, node));
    CHECK(rig.pan.object(od::kTpdoComm, 5) == 5u);
    CHECK(rig.tilt.object(od::kConsumerHeartbeat, 1) == ((127u << 16) | 100u));
    CHECK(rig.pan.nmt_state() == static_cast<std::uint8_t>(NmtState::PreOperational));
    CHECK(rig.pan.state() == DriveState::SwitchOnDisabled);

    REQUIRE(rig.driver->activate().ok);
    CHECK(rig.pan.nmt_state() == static_cast<std::uint8_t>(NmtState::Operational));
    CHECK(rig.pan.state() == DriveState::OperationEnabled);
    CHECK(rig.tilt.state() == DriveState::OperationEnabled);
    // The controlwords that took it there: shutdown, switch on, enable operation (RPDO1 bytes 0-1).
    bool shutdown = false, switch_on = false, enable = false;
    for (const auto& r : frames_with_id(rig.pan, rpdo_id(1, node))) {
        const int word = r.frame.data[0] | (r.frame.data[1] << 8);
        shutdown |= word == cw::kShutdown;
        switch_on |= word == cw::kSwitchOn;
        enable |= word == cw::kEnableOperation;
    }
    CHECK((shutdown && switch_on && enable));
    CHECK(rig.run(velocities(0, 0), 0.05));
    CHECK(rig.state.axes[0].enabled);
    CHECK(rig.state.axes[1].enabled);
    CHECK(rig.state.axes[0].homed);
    rig.driver->deactivate();
}

TEST_CASE("canopen: velocity commands move the drives and their positions come back by TPDO", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    CHECK(rig.run_until(velocities(0.5, -0.3), [&] {  // travelled a while, the position read back by TPDO
        return rig.status.ok && rig.pan.position_rad() > 0.2 && rig.tilt.position_rad() < -0.1 &&
               std::abs(rig.state.axes[0].position_rad - rig.pan.position_rad()) < 0.02;
    }));
    CHECK(rig.pan.velocity_rad_s() == Approx(0.5).margin(1e-3));
    CHECK(rig.tilt.velocity_rad_s() == Approx(-0.3).margin(1e-3));
    // The target velocity the drive received, in counts/s (RPDO1 bytes 3-6, mode byte 2 = 3).
    const auto rpdos = frames_with_id(rig.pan, rpdo_id(1, 1));
    REQUIRE(!rpdos.empty());
    const can_frame& last = rpdos.back().frame;
    const auto counts = static_cast<std::int32_t>(last.data[3] | (last.data[4] << 8) | (last.data[5] << 16) |
                                                  (static_cast<std::uint32_t>(last.data[6]) << 24));
    CHECK(counts == static_cast<std::int32_t>(std::lround(0.5 * 131072 / (2 * M_PI))));
    CHECK(last.data[2] == kProfileVelocity);
    CHECK(rig.state.axes[1].velocity_rad_s == Approx(-0.3).margin(0.01));
    rig.driver->deactivate();
    CHECK(rays::test::eventually([&] {  // quick stop, then pre-operational
        return rig.pan.state() == DriveState::SwitchOnDisabled &&
               rig.pan.nmt_state() == static_cast<std::uint8_t>(NmtState::PreOperational);
    }));
}

TEST_CASE("canopen: position commands use profile position with new set-point and change immediately", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    REQUIRE(rig.run_until(positions(0.4, -0.2), [&] {
        return std::abs(rig.pan.position_rad() - 0.4) < 1e-3 && std::abs(rig.tilt.position_rad() + 0.2) < 1e-3;
    }));
    bool set_point = false;
    for (const auto& r : frames_with_id(rig.pan, rpdo_id(2, 1))) {
        const int word = r.frame.data[0] | (r.frame.data[1] << 8);
        const auto target = static_cast<std::int32_t>(r.frame.data[3] | (r.frame.data[4] << 8) |
                                                      (r.frame.data[5] << 16) | (static_cast<std::uint32_t>(r.frame.data[6]) << 24));
        if ((word & cw::kNewSetPoint) && (word & cw::kChangeSetImmediately) && r.frame.data[2] == kProfilePosition)
            set_point |= target == static_cast<std::int32_t>(std::lround(0.4 * 131072 / (2 * M_PI)));
    }
    CHECK(set_point);
    // A new target replaces the old one at once.
    REQUIRE(rig.run_until(positions(-0.1, 0.0), [&] { return std::abs(rig.pan.position_rad() + 0.1) < 1e-3; }));
    CHECK(rig.run_until(velocities(0, 0), [&] {
        return rig.status.ok && std::abs(rig.state.axes[0].position_rad + 0.1) < 1e-3;
    }));
    rig.driver->deactivate();
}

TEST_CASE("canopen: a position move cruises at the drives' profile velocity (0x6081), not at their top speed", "[canopen]") {
    CanopenSettings settings = rays::test::fast_canopen_settings();
    settings.max_velocity_deg_s = 45.0;  // the simulated drives reach 3 rad/s (172 deg/s)
    CanopenRig rig(settings);
    bring_up(rig);
    const std::optional<double> fastest = rays::test::fastest_pan_move(rig, 0.6);
    REQUIRE(fastest);
    CHECK(*fastest * 180.0 / M_PI == Approx(45.0).epsilon(0.01));
    rig.driver->deactivate();
}

TEST_CASE("canopen: a drive fault stops the other axis, is reset once cleared, and the axes recover", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    REQUIRE(rig.run_until(velocities(0.5, 0.5), [&] {
        return rig.status.ok && std::abs(rig.tilt.velocity_rad_s() - 0.5) < 1e-3;
    }));
    rig.pan.inject_fault(0x2310);  // continuous over-current
    REQUIRE(rig.run_until(velocities(0.5, 0.5), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "pan (node 1): drive fault"));
    CHECK(contains(rig.status, "EMCY 0x2310"));
    CHECK(rig.run_until(velocities(0.5, 0.5), [&] { return rig.state.axes[0].fault; }));
    // Still commanded to move, the tilt drive is stopped.
    CHECK(rig.run_until(velocities(0.5, 0.5), [&] { return rig.tilt.velocity_rad_s() == 0.0; }));
    CHECK(rig.pan.velocity_rad_s() == 0.0);
    CHECK(rig.pan.state() == DriveState::Fault);
    // The fault stays while its cause does; once cleared, a fault reset (bit 7 rising) takes effect.
    rig.pan.clear_fault();
    REQUIRE(rig.run_until(velocities(0.5, 0.5), [&] { return rig.status.ok && rig.state.axes[0].enabled; }));
    bool reset = false;
    for (const auto& r : frames_with_id(rig.pan, rpdo_id(1, 1))) reset |= (r.frame.data[0] & cw::kFaultReset) != 0;
    CHECK(reset);
    CHECK(rig.run_until(velocities(0.5, 0.5), [&] {
        return std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3 && std::abs(rig.tilt.velocity_rad_s() - 0.5) < 1e-3;
    }));
    rig.driver->deactivate();
}

TEST_CASE("canopen: a drive whose heartbeat stops is a fault, both axes stop, it recovers when it returns", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.4, 0.4), 0.2));
    rig.tilt.stop_heartbeat(true);
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "tilt (node 2): heartbeat lost"));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] { return rig.pan.velocity_rad_s() == 0.0; }));
    rig.tilt.stop_heartbeat(false);
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return rig.status.ok && rig.state.axes[1].enabled; }));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] { return std::abs(rig.tilt.velocity_rad_s() - 0.4) < 1e-3; }));
    rig.driver->deactivate();
}

TEST_CASE("canopen: when raysd's heartbeat stops (killed), the drives stop by their own consumer watchdog", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    REQUIRE(rig.run_until(velocities(0.5, -0.5), [&] {
        return rig.status.ok && std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3;
    }));
    // As after SIGKILL: nothing the driver sends reaches the bus any more (no stop, no heartbeat).
    rig.driver_end.mute(true);
    const auto killed = MonoClock::now();
    CHECK(rays::test::eventually([&] {  // the consumer heartbeat times out, then the quick-stop ramp
        return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0 &&
               rig.pan.state() == DriveState::SwitchOnDisabled;
    }));
    CHECK(rig.pan.communication_losses() == 1);
    CHECK(rig.tilt.communication_losses() == 1);
    // Nothing from raysd went onto the bus after the mute but the one send its I/O thread may have had
    // under way.
    int after_mute = 0;
    for (const auto& record : rig.bus.records())
        after_mute += record.sender == rig.driver_end.number() && record.time > killed;
    CHECK(after_mute <= 1);
    rig.driver_end.mute(false);
    rig.driver->deactivate();
}

TEST_CASE("canopen: a stale command stream stops the axes", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    REQUIRE(rig.run_until(velocities(0.5, 0.5), [&] {
        return rig.status.ok && std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3;
    }));
    // No write() from here: after command_timeout_s (0.3 s) the driver stops the axes by itself.
    CHECK(rays::test::eventually([&] { return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0; }));
    const auto rpdos = frames_with_id(rig.pan, rpdo_id(1, 1));
    const can_frame& last = rpdos.back().frame;
    CHECK((last.data[3] | last.data[4] | last.data[5] | last.data[6]) == 0);
    rig.driver->deactivate();
}

TEST_CASE("canopen: an SDO abort fails configure with the abort code and the object", "[canopen]") {
    CanopenRig rig;
    rig.pan.abort_sdo(od::kAbortConnection, 0x06090030);
    const ptu::DriverStatus status = rig.driver->configure();
    CHECK_FALSE(status.ok);
    INFO(status.what());
    CHECK(contains(status, "pan (node 1): SDO abort 0x06090030 (value range of parameter exceeded) writing 0x6007:00"));
}

TEST_CASE("canopen: a drive that does not answer fails configure with an SDO timeout", "[canopen]") {
    CanopenRig rig;
    rig.tilt.mute(true);
    const ptu::DriverStatus status = rig.driver->configure();
    CHECK_FALSE(status.ok);
    INFO(status.what());
    CHECK(contains(status, "tilt (node 2): no SDO reply to 0x6040:00 within 50 ms"));
}

TEST_CASE("canopen: bus-off is a fault on both axes, the drives stop, all recovers when the bus is back", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.3, 0.3), 0.2));
    rig.bus.set_bus_off(true);
    REQUIRE(rig.run_until(velocities(0.3, 0.3), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "CAN bus-off"));
    // No frame passes: the drives' consumer heartbeat stops them.
    CHECK(rig.run_until(velocities(0.3, 0.3), [&] {
        return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0;
    }));
    CHECK(rig.state.axes[0].fault);
    rig.bus.set_bus_off(false);
    REQUIRE(rig.run_until(velocities(0.3, 0.3), [&] {
        return rig.status.ok && rig.state.axes[0].enabled && rig.state.axes[1].enabled;
    }));
    CHECK(rig.run_until(velocities(0.3, 0.3), [&] { return std::abs(rig.pan.velocity_rad_s() - 0.3) < 1e-3; }));
    rig.driver->deactivate();
}

TEST_CASE("canopen: ENOBUFS on send is retried and counted, dropped frames do not stop the loop", "[canopen]") {
    CanopenRig rig;
    bring_up(rig);
    rig.driver_end.fail_sends_with_enobufs(3);
    CHECK(rig.run(velocities(0.2, 0.2), 0.2));
    CHECK(rig.driver_end.counters().enobufs_retries == 3);
    CHECK(rig.driver_end.counters().dropped == 0);
    rig.driver_end.fail_sends_with_enobufs(20);  // four frames given up after their retries
    CHECK(rig.run(velocities(0.2, 0.2), 0.3));
    CHECK(rig.driver_end.counters().dropped == 4);
    CHECK(rig.pan.velocity_rad_s() == Approx(0.2).margin(1e-3));
    rig.driver->deactivate();
}

TEST_CASE("canopen: the factory refuses invalid combinations", "[canopen]") {
    SteadyClock clock;
    std::string error;
    CanopenSettings settings;
    settings.tilt_node_id = settings.pan_node_id;
    CHECK(make_canopen_driver(settings, clock, error) == nullptr);
    CHECK(error == "canopen: pan_node_id and tilt_node_id must differ");
    settings = CanopenSettings{};
    settings.master_id = settings.pan_node_id;
    CHECK(make_canopen_driver(settings, clock, error) == nullptr);
    CHECK(error == "canopen: master_id must differ from the drives' node ids");
    settings = CanopenSettings{};
    CHECK(make_canopen_driver(settings, clock, error) != nullptr);
}

TEST_CASE("canopen: the parameter table names every key of the canopen section with its unit", "[canopen]") {
    const auto& table = canopen_params();
    REQUIRE(table.find("canopen.interface") != nullptr);
    REQUIRE(table.find("canopen.master_heartbeat_ms") != nullptr);
    CHECK(table.find("canopen.master_heartbeat_ms")->info.unit == "ms");
    CHECK(table.find("canopen.comm_loss_action")->info.choices == "quick_stop|disable_voltage|fault");
    CanopenSettings settings;
    settings.drive_consumer_timeout_ms = settings.master_heartbeat_ms;
    CHECK(table.check_rules(settings).has_value());
    CHECK_FALSE(table.check_rules(CanopenSettings{}).has_value());
    for (const auto& section : table.sections()) CHECK(section == "canopen");
}

TEST_CASE("canopen: raysd --stop-axes (configure, stop, deactivate) stops drives a killed run left moving", "[canopen]") {
    auto settings = rays::test::fast_canopen_settings();
    settings.drive_consumer_timeout_ms = 5000;  // so that the stop comes from configure, not the watchdog
    CanopenRig rig(settings);
    bring_up(rig);
    REQUIRE(rig.run_until(velocities(0.5, -0.5), [&] {
        return rig.status.ok && std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3;
    }));
    rig.driver_end.mute(true);  // killed: its last frames never arrive
    rig.driver.reset();
    REQUIRE(rig.pan.velocity_rad_s() == Approx(0.5).margin(1e-3));
    std::string error;
    auto stopper = make_canopen_driver(settings, rig.bus.transport_for(rig.bus.add_endpoint()), rig.clock, error);
    REQUIRE(stopper->configure().ok);
    CHECK(rig.pan.state() == DriveState::SwitchOnDisabled);  // SDO quick stop first
    (void)stopper->write(ptu::PtuCommand::stop(), rig.clock.now());
    stopper->deactivate();
    CHECK(rays::test::eventually([&] { return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0; }));
    CHECK(rig.pan.communication_losses() == 0);
}
