// SPDX-License-Identifier: Apache-2.0
// A MockPtu behind a PtuLimiter on a manual clock, configured, active and placed at time 0.
#pragma once
#include <catch2/catch.hpp>

#include "drivers/mock/mock_ptu.hpp"
#include "drivers/ptu_limiter.hpp"
#include "manual_clock.hpp"

namespace rays::test {

// Limits [min, max] on both axes with the same rates, and a mock whose rates match them.
inline ptu::PtuLimits symmetric_limits(double min_rad, double max_rad, double vmax, double amax) {
    ptu::PtuLimits limits;
    limits.axes[0] = {min_rad, max_rad, vmax, amax};
    limits.axes[1] = {min_rad, max_rad, vmax, amax};
    return limits;
}

inline ptu::MockPtuConfig matched_mock(const ptu::PtuLimits& limits, double latency_s) {
    ptu::MockPtuConfig config;
    config.max_velocity_rad_s = limits.axes[0].max_velocity_rad_s;
    config.max_accel_rad_s2 = limits.axes[0].max_accel_rad_s2;
    config.latency_s = latency_s;
    for (std::size_t i = 0; i < ptu::kAxes; ++i)  // end stops well outside, so overshoot shows
        config.end_stops[i] = {limits.axes[i].min_rad - 1.0, limits.axes[i].max_rad + 1.0};
    config.record_capacity = 10000;
    return config;
}

struct LimiterRig {
    LimiterRig(const ptu::MockPtuConfig& mock_config, const ptu::PtuLimits& limits)
        : mock(mock_config, clock), limiter(mock) {
        limiter.set_limits(limits);
        REQUIRE(limiter.configure().ok);
        REQUIRE(limiter.activate().ok);
        ptu::PtuState state;
        REQUIRE(limiter.read(state, at_seconds(0.0)).ok);
    }

    ManualClock clock;
    ptu::MockPtu mock;
    ptu::PtuLimiter limiter;
};

inline ptu::PtuCommand both_axes(ptu::CommandMode mode, double pan, double tilt) {
    ptu::PtuCommand command;
    command.axes[0] = {mode, pan};
    command.axes[1] = {mode, tilt};
    return command;
}

}  // namespace rays::test
