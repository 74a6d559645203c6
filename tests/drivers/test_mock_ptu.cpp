// SPDX-License-Identifier: Apache-2.0
// MockPtu: records, lifecycle, faults, state from its axis dynamics; DriverStatus messages.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <thread>

#include "drivers/mock/mock_ptu.hpp"
#include "manual_clock.hpp"

namespace {

using rays::test::at_seconds;
using rays::test::ManualClock;
using namespace rays::ptu;

PtuCommand velocities(double pan, double tilt) {
    PtuCommand command;
    command.axes[0] = {CommandMode::Velocity, pan};
    command.axes[1] = {CommandMode::Velocity, tilt};
    return command;
}

MockPtuConfig quick_config() {
    MockPtuConfig config;
    config.max_velocity_rad_s = 1.0;
    config.max_accel_rad_s2 = 10.0;
    config.latency_s = 0.0;
    config.record_capacity = 8;
    return config;
}

}  // namespace

TEST_CASE("DriverStatus::failure keeps a short message and cuts a long one", "[mock]") {
    CHECK(DriverStatus::success().ok);
    CHECK(std::string(DriverStatus::success().what()).empty());
    const DriverStatus status = DriverStatus::failure("bus timeout");
    CHECK_FALSE(status.ok);
    CHECK(std::string(status.what()) == "bus timeout");
    const std::string long_text(500, 'x');
    const DriverStatus cut = DriverStatus::failure(long_text.c_str());
    CHECK(std::strlen(cut.what()) == cut.message.size() - 1);
    CHECK_FALSE(DriverStatus::failure(nullptr).ok);
}

TEST_CASE("MockPtu records every write with its time, and counts what does not fit", "[mock]") {
    ManualClock clock;
    MockPtu ptu(quick_config(), clock);
    REQUIRE(ptu.configure().ok);
    CHECK_FALSE(ptu.write(velocities(0.1, 0.0), at_seconds(0.5)).ok);  // not active yet: recorded as refused
    REQUIRE(ptu.activate().ok);
    for (int i = 1; i <= 10; ++i) ptu.write(velocities(0.1 * i, -0.1 * i), at_seconds(1.0 + 0.1 * i));
    const auto records = ptu.records();
    REQUIRE(records.size() == 8);
    CHECK(ptu.dropped_records() == 3);
    CHECK_FALSE(records[0].accepted);
    CHECK(records[0].time == at_seconds(0.5));
    for (std::size_t i = 1; i < records.size(); ++i) {
        INFO("record " << i);
        CHECK(records[i].accepted);
        CHECK(records[i].time == at_seconds(1.0 + 0.1 * static_cast<double>(i)));
        CHECK(records[i].command.axes[0].value == Approx(0.1 * static_cast<double>(i)));
        CHECK(records[i].command.axes[1].value == Approx(-0.1 * static_cast<double>(i)));
    }
}

TEST_CASE("MockPtu enforces the lifecycle order and moves only while active", "[mock]") {
    ManualClock clock;
    MockPtu ptu(quick_config(), clock);
    PtuState state;
    CHECK_FALSE(ptu.read(state, at_seconds(0.0)).ok);
    CHECK_FALSE(ptu.activate().ok);
    CHECK_FALSE(ptu.active());
    REQUIRE(ptu.configure().ok);
    CHECK(ptu.configured());
    CHECK_FALSE(ptu.write(velocities(1.0, 1.0), at_seconds(0.0)).ok);
    REQUIRE(ptu.read(state, at_seconds(1.0)).ok);
    CHECK(state.axes[0].position_rad == 0.0);
    CHECK_FALSE(state.axes[0].enabled);
    CHECK(state.axes[0].homed);

    REQUIRE(ptu.activate().ok);
    CHECK_FALSE(ptu.configure().ok);  // not while active
    REQUIRE(ptu.write(velocities(1.0, -0.5), at_seconds(1.0)).ok);
    REQUIRE(ptu.read(state, at_seconds(2.0)).ok);
    CHECK(state.stamp == at_seconds(2.0));
    CHECK(state.axes[0].enabled);
    CHECK(state.axes[0].velocity_rad_s == 1.0);
    CHECK(state.axes[0].position_rad == Approx(0.05 + 0.9));  // 0.1 s ramp, then 0.9 s at 1 rad/s
    CHECK(state.axes[1].velocity_rad_s == -0.5);

    clock.set_seconds(2.0);
    ptu.deactivate();  // halts both axes from the clock's time
    CHECK_FALSE(ptu.active());
    CHECK_FALSE(ptu.write(velocities(1.0, 1.0), at_seconds(2.5)).ok);
    REQUIRE(ptu.read(state, at_seconds(3.0)).ok);
    CHECK(state.axes[0].velocity_rad_s == 0.0);
    CHECK(state.axes[1].velocity_rad_s == 0.0);
    CHECK_FALSE(state.axes[0].enabled);

    const auto calls = ptu.lifecycle_calls();
    REQUIRE(calls.size() == 5);
    const LifecycleStep steps[] = {LifecycleStep::Activate, LifecycleStep::Configure, LifecycleStep::Activate,
                                   LifecycleStep::Configure, LifecycleStep::Deactivate};
    const bool oks[] = {false, true, true, false, true};
    for (std::size_t i = 0; i < calls.size(); ++i) {
        INFO("call " << i);
        CHECK(calls[i].step == steps[i]);
        CHECK(calls[i].ok == oks[i]);
    }
}

TEST_CASE("MockPtu reports the dynamics' state at the time read, latency included", "[mock]") {
    ManualClock clock;
    MockPtuConfig config = quick_config();
    config.latency_s = 0.05;
    MockPtu ptu(config, clock);
    REQUIRE(ptu.configure().ok);
    REQUIRE(ptu.activate().ok);
    REQUIRE(ptu.write(velocities(1.0, 0.0), at_seconds(0.0)).ok);
    PtuState state;
    REQUIRE(ptu.read(state, at_seconds(0.049)).ok);
    CHECK(state.axes[0].velocity_rad_s == 0.0);
    REQUIRE(ptu.read(state, at_seconds(0.1)).ok);
    CHECK(state.axes[0].velocity_rad_s == Approx(0.5));
}

TEST_CASE("MockPtu stops both axes on a fault, refuses writes and recovers when cleared", "[mock]") {
    ManualClock clock;
    MockPtu ptu(quick_config(), clock);
    REQUIRE(ptu.configure().ok);
    REQUIRE(ptu.activate().ok);
    REQUIRE(ptu.write(velocities(1.0, 1.0), at_seconds(0.0)).ok);
    clock.set_seconds(1.0);
    ptu.inject_fault(Axis::Tilt, "overcurrent");
    const DriverStatus refused = ptu.write(velocities(0.5, 0.5), at_seconds(1.0));
    CHECK_FALSE(refused.ok);
    CHECK(std::string(refused.what()).find("tilt") != std::string::npos);
    CHECK(std::string(refused.what()).find("overcurrent") != std::string::npos);
    PtuState state;
    REQUIRE(ptu.read(state, at_seconds(2.0)).ok);
    CHECK(state.axes[1].fault);
    CHECK_FALSE(state.axes[1].enabled);
    CHECK(state.axes[1].velocity_rad_s == 0.0);
    CHECK_FALSE(state.axes[0].fault);
    CHECK(state.axes[0].velocity_rad_s == 0.0);  // the healthy axis was stopped as well

    ptu.clear_fault();
    REQUIRE(ptu.write(velocities(0.0, -1.0), at_seconds(2.0)).ok);
    REQUIRE(ptu.read(state, at_seconds(3.0)).ok);
    CHECK_FALSE(state.axes[1].fault);
    CHECK(state.axes[1].enabled);
    CHECK(state.axes[1].velocity_rad_s == -1.0);
}

TEST_CASE("MockPtu records are readable from another thread once the writer stopped", "[mock]") {
    ManualClock clock;
    MockPtuConfig config = quick_config();
    config.record_capacity = 1000;
    MockPtu ptu(config, clock);
    REQUIRE(ptu.configure().ok);
    REQUIRE(ptu.activate().ok);
    std::thread frame_loop([&] {
        PtuState state;
        for (int i = 0; i < 1000; ++i) {
            ptu.write(velocities(0.001 * i, 0.0), at_seconds(0.01 * i));
            ptu.read(state, at_seconds(0.01 * i));
        }
    });
    frame_loop.join();
    const auto records = ptu.records();
    REQUIRE(records.size() == 1000);
    CHECK(records[999].command.axes[0].value == Approx(0.999));
}
