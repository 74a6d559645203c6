// SPDX-License-Identifier: Apache-2.0
// make_ptu_driver's settings: each drive's own position-move profile held within [ptu]'s soft limits,
// and a CiA 402 drive on the in-memory bus configured from them moving at the soft limit.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>

#include "canopen_rig.hpp"
#include "daemon/ptu_factory.hpp"

using namespace rays;
using namespace rays::daemon;

TEST_CASE("ptu factory: every drive's position moves are held within the soft velocity limit") {
    DaemonConfig config;
    config.ptu.motion.max_velocity_deg_s = 40.0;
    config.ptu.motion.max_accel_deg_s2 = 200.0;
    config.gpio.homing_speed_deg_s = 50.0;
    config.canopen.interface = "can1";
    const DaemonConfig held = with_moves_within_soft_limits(config);
    CHECK(held.canopen.max_velocity_deg_s == 40.0);  // from 120
    CHECK(held.odrive.max_velocity_deg_s == 40.0);
    CHECK(held.gpio.max_velocity_deg_s == 40.0);  // from 90
    CHECK(held.gpio.homing_speed_deg_s == 40.0);
    // Accelerations as configured: a drive's deceleration also stops it.
    CHECK(held.canopen.accel_deg_s2 == 600.0);
    CHECK(held.odrive.accel_deg_s2 == 600.0);
    CHECK(held.gpio.max_accel_deg_s2 == 360.0);
    CHECK(held.pwm.move_speed_deg_s == 40.0);
    CHECK(held.canopen.interface == "can1");  // the rest as given

    // A drive set slower than the soft limit keeps its own profile.
    config.canopen.max_velocity_deg_s = 20.0;
    CHECK(with_moves_within_soft_limits(config).canopen.max_velocity_deg_s == 20.0);
}

TEST_CASE("ptu factory: a CiA 402 drive configured from the defaults goes to a position at the soft velocity limit") {
    DaemonConfig config;  // [canopen] max_velocity_deg_s 120, [ptu] max_velocity_deg_s 90
    const canopen::CanopenSettings timing = test::fast_canopen_settings();
    config.canopen.master_heartbeat_ms = timing.master_heartbeat_ms;
    config.canopen.drive_consumer_timeout_ms = timing.drive_consumer_timeout_ms;
    config.canopen.drive_heartbeat_ms = timing.drive_heartbeat_ms;
    config.canopen.drive_heartbeat_timeout_ms = timing.drive_heartbeat_timeout_ms;
    config.canopen.tpdo_period_ms = timing.tpdo_period_ms;
    config.canopen.cycle_ms = timing.cycle_ms;
    REQUIRE(config.canopen.max_velocity_deg_s > config.ptu.motion.max_velocity_deg_s);
    test::CanopenRig rig(with_moves_within_soft_limits(config).canopen);  // the drives reach 172 deg/s
    REQUIRE(rig.driver != nullptr);
    REQUIRE(rig.driver->configure().ok);
    REQUIRE(rig.driver->activate().ok);
    const std::optional<double> fastest = test::fastest_pan_move(rig, 1.0);
    REQUIRE(fastest);
    CHECK(*fastest * 180.0 / M_PI == Approx(90.0).epsilon(0.01));
    rig.driver->deactivate();
}
