// SPDX-License-Identifier: Apache-2.0
// The ODrive driver against two simulated ODrive axes on the in-memory bus; checks read the
// simulated axes (their received frames and motion).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "canopen_rig.hpp"
#include "odrive_rig.hpp"

using namespace rays;
using namespace rays::odrive;
using rays::test::commands_received;
using rays::test::OdriveRig;
using rays::test::positions;
using rays::test::velocities;

namespace {

bool contains(const ptu::DriverStatus& status, const char* text) { return std::strstr(status.what(), text) != nullptr; }

void bring_up(OdriveRig& rig) {
    REQUIRE(rig.driver != nullptr);
    const ptu::DriverStatus configured = rig.driver->configure();
    INFO(configured.what());
    REQUIRE(configured.ok);
    const ptu::DriverStatus activated = rig.driver->activate();
    INFO(activated.what());
    REQUIRE(activated.ok);
}

bool has(const std::vector<Cmd>& commands, Cmd cmd) { return std::find(commands.begin(), commands.end(), cmd) != commands.end(); }

}  // namespace

TEST_CASE("odrive: bring-up clears errors, sets the controller mode and enters closed loop control", "[odrive]") {
    OdriveRig rig;
    REQUIRE(rig.driver->configure().ok);
    CHECK(rig.pan.axis_state() == kAxisIdle);  // configure moves nothing
    CHECK(rig.pan.received().empty());
    REQUIRE(rig.driver->activate().ok);
    CHECK(rig.pan.axis_state() == kAxisClosedLoop);
    CHECK(rig.tilt.axis_state() == kAxisClosedLoop);
    const auto commands = commands_received(rig.pan);
    REQUIRE(commands.size() >= 6);
    CHECK(commands[0] == Cmd::ClearErrors);
    CHECK(has(commands, Cmd::SetTrajVelLimit));
    CHECK(has(commands, Cmd::SetTrajAccelLimits));
    CHECK(has(commands, Cmd::SetControllerMode));
    CHECK(has(commands, Cmd::SetAxisState));
    CHECK(rig.run(velocities(0, 0), 0.05));
    CHECK(rig.state.axes[0].enabled);
    rig.driver->deactivate();
    CHECK(rays::test::eventually([&] { return rig.pan.axis_state() == kAxisIdle; }));
}

TEST_CASE("odrive: velocity and position commands move the axes through the gear ratio", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run_until(velocities(0.5, -0.3), [&] {  // up to speed, and the driver reading that speed back
        return rig.status.ok && std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3 &&
               std::abs(rig.tilt.velocity_rad_s() + 0.3) < 1e-3 &&
               std::abs(rig.state.axes[0].velocity_rad_s - 0.5) < 0.01;
    }));
    // Set_Input_Vel in motor turns/s: 0.5 rad/s × 10 turns per turn / 2π.
    const auto received = rig.pan.received();
    const auto last = std::find_if(received.rbegin(), received.rend(), [](const auto& r) {
        return cmd_of(r.frame.can_id & CAN_SFF_MASK) == Cmd::SetInputVel;
    });
    REQUIRE(last != received.rend());
    CHECK(can::get_f32(last->frame, 0) == Approx(0.5 * 10 / (2 * M_PI)).epsilon(1e-5));
    REQUIRE(rig.run_until(positions(0.3, 0.2), [&] {
        return std::abs(rig.pan.position_rad() - 0.3) < 1e-3 && std::abs(rig.tilt.position_rad() - 0.2) < 1e-3;
    }));
    CHECK(has(commands_received(rig.pan), Cmd::SetInputPos));
    CHECK(rig.run_until(positions(0.3, 0.2), [&] {
        return rig.status.ok && std::abs(rig.state.axes[0].position_rad - 0.3) < 1e-3;
    }));
    rig.driver->deactivate();
}

TEST_CASE("odrive: a position move cruises at the trajectory velocity limit, not at the axis' top speed", "[odrive]") {
    OdriveSettings settings = rays::test::fast_odrive_settings();
    settings.max_velocity_deg_s = 45.0;  // the simulated axes reach 3 rad/s (172 deg/s)
    OdriveRig rig(settings);
    bring_up(rig);
    const std::optional<double> fastest = rays::test::fastest_pan_move(rig, 0.6);
    REQUIRE(fastest);
    CHECK(*fastest * 180.0 / M_PI == Approx(45.0).epsilon(0.01));
    rig.driver->deactivate();
}

TEST_CASE("odrive: an axis error stops the other axis, clears once its cause is gone, and the axes recover", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.4, 0.4), 0.2));
    rig.tilt.inject_error(0x00000100);  // e.g. MOTOR_FAILED
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "tilt (node 1): axis error 0x00000100"));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] {
        return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0;
    }));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] { return rig.state.axes[1].fault; }));
    rig.tilt.clear_fault();
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return rig.status.ok && rig.state.axes[1].enabled; }));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] {
        return std::abs(rig.pan.velocity_rad_s() - 0.4) < 1e-3 && std::abs(rig.tilt.velocity_rad_s() - 0.4) < 1e-3;
    }));
    rig.driver->deactivate();
}

TEST_CASE("odrive: a lost heartbeat is a fault, both axes stop, and it recovers when the heartbeat returns", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.4, 0.4), 0.2));
    rig.pan.stop_heartbeat(true);
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "pan (node 0): heartbeat lost"));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] { return rig.tilt.velocity_rad_s() == 0.0; }));
    rig.pan.stop_heartbeat(false);
    REQUIRE(rig.run_until(velocities(0.4, 0.4), [&] { return rig.status.ok && rig.state.axes[0].enabled; }));
    CHECK(rig.run_until(velocities(0.4, 0.4), [&] { return std::abs(rig.pan.velocity_rad_s() - 0.4) < 1e-3; }));
    rig.driver->deactivate();
}

TEST_CASE("odrive: when raysd stops sending (killed), the ODrive watchdog idles the axes", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.5, 0.5), 0.2));
    rig.driver_end.mute(true);
    CHECK(rays::test::eventually([&] {
        return rig.pan.axis_state() == kAxisIdle && rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0;
    }));
    CHECK((rig.pan.axis_error() & kErrorWatchdogExpired) != 0);
    // The driver sees the watchdog error in the heartbeat and says so.
    CHECK(rays::test::eventually([&] {
        return contains(rig.driver->read(rig.state, rig.clock.now()), "watchdog expired");
    }));
    rig.driver_end.mute(false);
    rig.driver->deactivate();
}

TEST_CASE("odrive: a stale command stream stops the axes", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.5, 0.5), 0.2));
    // No write() from here: after command_timeout_s (0.3 s) the driver stops the axes by itself.
    CHECK(rays::test::eventually([&] { return rig.pan.velocity_rad_s() == 0.0 && rig.tilt.velocity_rad_s() == 0.0; }));
    CHECK(rig.pan.axis_state() == kAxisClosedLoop);  // held at zero velocity, watchdog still fed
    rig.driver->deactivate();
}

TEST_CASE("odrive: configure fails when an axis sends no heartbeat", "[odrive]") {
    OdriveRig rig(rays::test::fast_odrive_settings(), 0.1, true);
    const ptu::DriverStatus status = rig.driver->configure();
    CHECK_FALSE(status.ok);
    INFO(status.what());
    CHECK(contains(status, "odrive: tilt (node 1): no heartbeat within 2.0 s"));
}

TEST_CASE("odrive: bus-off is a fault and all recovers when the bus is back", "[odrive]") {
    OdriveRig rig;
    bring_up(rig);
    CHECK(rig.run(velocities(0.3, 0.3), 0.2));
    rig.bus.set_bus_off(true);
    REQUIRE(rig.run_until(velocities(0.3, 0.3), [&] { return !rig.status.ok; }));
    CHECK(contains(rig.status, "CAN bus-off"));
    CHECK(rig.run_until(velocities(0.3, 0.3), [&] { return rig.pan.velocity_rad_s() == 0.0; }));
    rig.bus.set_bus_off(false);
    REQUIRE(rig.run_until(velocities(0.3, 0.3), [&] {
        return rig.status.ok && rig.state.axes[0].enabled && rig.state.axes[1].enabled;
    }));
    CHECK(rig.run_until(velocities(0.3, 0.3), [&] { return std::abs(rig.pan.velocity_rad_s() - 0.3) < 1e-3; }));
    rig.driver->deactivate();
}

TEST_CASE("odrive: the factory and the parameter table", "[odrive]") {
    SteadyClock clock;
    std::string error;
    OdriveSettings settings;
    settings.tilt_node_id = settings.pan_node_id;
    CHECK(make_odrive_driver(settings, clock, error) == nullptr);
    CHECK(error == "odrive: pan_node_id and tilt_node_id must differ");
    CHECK(make_odrive_driver(OdriveSettings{}, clock, error) != nullptr);
    const auto& table = odrive_params();
    REQUIRE(table.find("odrive.interface") != nullptr);
    CHECK(table.find("odrive.heartbeat_timeout_ms")->info.unit == "ms");
    for (const auto& section : table.sections()) CHECK(section == "odrive");
}

TEST_CASE("odrive: raysd --stop-axes (configure, stop, deactivate) idles an axis a killed run left moving", "[odrive]") {
    auto settings = rays::test::fast_odrive_settings();
    OdriveRig rig(settings, 5.0);  // a long ODrive watchdog: the stop must come from the stopper
    bring_up(rig);
    REQUIRE(rig.run_until(velocities(0.5, 0.5), [&] {
        return rig.status.ok && std::abs(rig.pan.velocity_rad_s() - 0.5) < 1e-3;
    }));
    rig.driver_end.mute(true);  // killed: its last frames never arrive
    rig.driver.reset();
    REQUIRE(rig.pan.velocity_rad_s() == Approx(0.5).margin(1e-3));
    std::string error;
    auto stopper = make_odrive_driver(settings, rig.bus.transport_for(rig.bus.add_endpoint()), rig.clock, error);
    REQUIRE(stopper->configure().ok);
    (void)stopper->write(ptu::PtuCommand::stop(), rig.clock.now());
    stopper->deactivate();
    CHECK(rays::test::eventually([&] { return rig.pan.axis_state() == kAxisIdle && rig.tilt.axis_state() == kAxisIdle; }));
    CHECK(rays::test::eventually([&] { return rig.pan.velocity_rad_s() == 0.0; }));
    CHECK(rig.pan.axis_error() == 0);  // idled by the command, not by the watchdog
}
