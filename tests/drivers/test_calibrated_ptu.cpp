// SPDX-License-Identifier: Apache-2.0
// Inversion and zero offset between the rig's angles and the unit's, checked on what the simulated
// unit received and reported.
#include <catch2/catch.hpp>

#include "drivers/calibrated_ptu.hpp"
#include "drivers/mock/mock_ptu.hpp"
#include "manual_clock.hpp"

using namespace rays::ptu;
using rays::test::at_seconds;

TEST_CASE("commands and states are mapped per axis: unit = sign * rig + zero") {
    rays::test::ManualClock clock;
    MockPtuConfig config;
    config.latency_s = 0.0;
    MockPtu unit(config, clock);
    CalibratedPtu rig(unit, {{{true, 0.1}, {false, -0.2}}});
    REQUIRE(rig.configure().ok);
    REQUIRE(rig.activate().ok);

    PtuCommand command;
    command.axes[0] = {CommandMode::Position, 0.3};
    command.axes[1] = {CommandMode::Velocity, 0.05};
    REQUIRE(rig.write(command, at_seconds(0)).ok);
    const CommandRecord& sent = unit.records().back();
    CHECK(sent.command.axes[0].value == Approx(-0.3 + 0.1));  // inverted, then offset
    CHECK(sent.command.axes[1].value == Approx(0.05));       // velocities carry no offset

    PtuState unit_state, rig_state;
    REQUIRE(unit.read(unit_state, at_seconds(5)).ok);
    REQUIRE(rig.read(rig_state, at_seconds(5)).ok);
    CHECK(unit_state.axes[0].position_rad == Approx(-0.2));
    CHECK(rig_state.axes[0].position_rad == Approx(0.3));  // back in the rig's angles
    CHECK(rig_state.axes[1].position_rad == Approx(unit_state.axes[1].position_rad + 0.2));
    CHECK(rig_state.axes[1].velocity_rad_s == Approx(unit_state.axes[1].velocity_rad_s));
    CHECK(std::string(rig.name()) == "mock");
    CHECK(rig.home(at_seconds(5)).ok);
}
