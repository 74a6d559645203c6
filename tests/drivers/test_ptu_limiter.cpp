// SPDX-License-Identifier: Apache-2.0
// PtuLimiter above a MockPtu: soft limits, velocity and acceleration limits, non-finite commands,
// mode switches, stop, staleness, and holding still until the unit is known.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "limiter_rig.hpp"

namespace {

using rays::test::at_seconds;
using rays::test::both_axes;
using rays::test::LimiterRig;
using rays::test::matched_mock;
using rays::test::symmetric_limits;
using namespace rays::ptu;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double seconds_between(rays::TimePoint a, rays::TimePoint b) { return std::chrono::duration<double>(b - a).count(); }

// One axis's random command, held for a random number of frames.
AxisCommand random_command(std::mt19937& rng, const AxisLimits& limits) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double vmax = limits.max_velocity_rad_s;
    const double kind = unit(rng);
    if (kind < 0.5) return {CommandMode::Velocity, (unit(rng) * 3.0 - 1.5) * vmax};
    if (kind < 0.65) return {CommandMode::Velocity, unit(rng) < 0.5 ? -1.5 * vmax : 1.5 * vmax};
    if (kind < 0.8) return {CommandMode::Position, limits.min_rad - 0.5 + unit(rng) * (limits.max_rad - limits.min_rad + 1.0)};
    if (kind < 0.9) {
        const double bad[] = {kNaN, kInf, -kInf};
        return {unit(rng) < 0.5 ? CommandMode::Velocity : CommandMode::Position, bad[rng() % 3]};
    }
    return {CommandMode::Velocity, 0.0};
}

// What one random command sequence did to a unit behind the limiter, as worst excesses.
struct SequenceResult {
    double outside = 0.0;  // how far the unit went beyond a soft limit
    double speed = 0.0;    // velocity commands beyond max_velocity
    double slew = 0.0;     // |Δv| between velocity commands beyond max_accel·dt
    double target = 0.0;   // position targets beyond the soft limits
    bool all_finite = true;
    double half_frame_travel = 0.0;  // max_velocity × longest frame / 2
};

// Random limits, latency and frame times; random commands held for random spans; the unit's
// position sampled 16 times a frame. The unit accelerates drive_accel_factor times as fast as the limits.
SequenceResult run_random_sequence(std::mt19937& rng, double drive_accel_factor) {
    constexpr int kFrames = 400;
    constexpr int kSamplesPerFrame = 16;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    PtuLimits limits;
    const double vmax = 0.3 + 2.7 * unit(rng);
    const double amax = 0.5 + 19.5 * unit(rng);
    for (AxisLimits& axis : limits.axes) axis = {-0.1 - 2.0 * unit(rng), 0.1 + 2.0 * unit(rng), vmax, amax};
    limits.command_interval_s = 0.03 + 0.17 * unit(rng);
    MockPtuConfig drive = matched_mock(limits, 0.15 * unit(rng));
    drive.max_accel_rad_s2 *= drive_accel_factor;
    LimiterRig rig(drive, limits);

    SequenceResult result;
    PtuCommand command;
    std::array<int, kAxes> held_for{};
    double t = 0.0;
    double longest_frame = 0.0;
    for (int frame = 0; frame < kFrames; ++frame) {
        for (std::size_t i = 0; i < kAxes; ++i)
            if (held_for[i]-- <= 0) {
                command.axes[i] = random_command(rng, limits.axes[i]);
                held_for[i] = static_cast<int>(rng() % 60);
            }
        rig.limiter.write(command, at_seconds(t));
        const double dt = limits.command_interval_s * (0.2 + 0.8 * unit(rng));
        longest_frame = std::max(longest_frame, dt);
        PtuState state;
        for (int k = 1; k <= kSamplesPerFrame; ++k) {
            rig.mock.read(state, at_seconds(t + dt * k / kSamplesPerFrame));
            for (std::size_t i = 0; i < kAxes; ++i) {
                const double x = state.axes[i].position_rad;
                result.outside = std::max({result.outside, x - limits.axes[i].max_rad, limits.axes[i].min_rad - x});
            }
        }
        t += dt;
        rig.limiter.read(state, at_seconds(t));
    }
    result.half_frame_travel = 0.5 * vmax * longest_frame;

    const auto records = rig.mock.records();
    for (std::size_t r = 0; r < records.size(); ++r)
        for (std::size_t i = 0; i < kAxes; ++i) {
            const AxisLimits& axis = limits.axes[i];
            const AxisCommand& sent = records[r].command.axes[i];
            result.all_finite = result.all_finite && std::isfinite(sent.value);
            if (sent.mode == CommandMode::Position) {
                result.target = std::max({result.target, sent.value - axis.max_rad, axis.min_rad - sent.value});
                continue;
            }
            result.speed = std::max(result.speed, std::abs(sent.value) - axis.max_velocity_rad_s);
            if (r == 0 || records[r - 1].command.axes[i].mode != CommandMode::Velocity) continue;
            const double dt = seconds_between(records[r - 1].time, records[r].time);
            const double dv = std::abs(sent.value - records[r - 1].command.axes[i].value);
            result.slew = std::max(result.slew, dv - axis.max_accel_rad_s2 * dt);
        }
    return result;
}

}  // namespace

TEST_CASE("PtuLimiter keeps a matched unit within its limits under random command sequences", "[limiter]") {
    std::mt19937 rng(20240611);
    for (int sequence = 0; sequence < 150; ++sequence) {
        const SequenceResult result = run_random_sequence(rng, 1.0);
        INFO("sequence " << sequence);
        CHECK(result.outside <= 1e-9);
        CHECK(result.speed <= 0.0);
        CHECK(result.slew <= 1e-9);
        CHECK(result.target <= 0.0);
        CHECK(result.all_finite);
    }
}

TEST_CASE("PtuLimiter keeps a faster unit within half a frame's travel of its limits", "[limiter]") {
    std::mt19937 rng(97);
    for (double faster : {1.5, 4.0, 50.0})
        for (int sequence = 0; sequence < 50; ++sequence) {
            const SequenceResult result = run_random_sequence(rng, faster);
            INFO("acceleration x" << faster << ", sequence " << sequence);
            CHECK(result.outside <= result.half_frame_travel);
            CHECK(result.speed <= 0.0);
        }
}

TEST_CASE("PtuLimiter brings an axis approaching a limit at full speed to rest before it", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-1.0, 1.0, 1.0, 2.0);
    LimiterRig rig(matched_mock(limits, 0.08), limits);
    constexpr double kFrame = 1.0 / 30.0;
    double peak_speed = 0.0;
    double furthest = 0.0;
    PtuState state;
    for (int frame = 0; frame < 150; ++frame) {
        const double t = kFrame * frame;
        rig.limiter.write(both_axes(CommandMode::Velocity, 1.0, -1.0), at_seconds(t));
        rig.limiter.read(state, at_seconds(t + kFrame));
        peak_speed = std::max(peak_speed, state.axes[0].velocity_rad_s);
        furthest = std::max({furthest, state.axes[0].position_rad, -state.axes[1].position_rad});
    }
    CHECK(peak_speed == Approx(1.0));
    CHECK(furthest <= 1.0 + 1e-9);
    CHECK(state.axes[0].position_rad > 1.0 - 1e-3);  // and it does get there
    CHECK(state.axes[1].position_rad < -1.0 + 1e-3);
    CHECK(state.axes[0].velocity_rad_s == Approx(0.0).margin(1e-6));
}

TEST_CASE("PtuLimiter lets an axis beyond a soft limit move back but not further out", "[limiter]") {
    PtuLimits limits = symmetric_limits(-1.0, 1.0, 1.0, 4.0);
    LimiterRig rig(matched_mock(limits, 0.0), limits);
    PtuState state;
    for (int frame = 0; frame <= 150; ++frame) rig.limiter.write(both_axes(CommandMode::Position, 0.8, 0.0), at_seconds(0.02 * frame));
    rig.limiter.read(state, at_seconds(3.0));
    REQUIRE(state.axes[0].position_rad == Approx(0.8));
    limits.axes[0].max_rad = 0.5;  // the axis is now beyond its limit
    rig.limiter.set_limits(limits);
    rig.limiter.write(both_axes(CommandMode::Velocity, 1.0, 0.0), at_seconds(3.1));
    CHECK(rig.mock.records().back().command.axes[0].value == 0.0);
    rig.limiter.write(both_axes(CommandMode::Velocity, -1.0, 0.0), at_seconds(3.2));
    CHECK(rig.mock.records().back().command.axes[0].value == Approx(-0.4));  // slewed at 4 rad/s² over 0.1 s
}

TEST_CASE("PtuLimiter turns non-finite commands into a ramp to rest", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-10.0, 10.0, 1.0, 5.0);
    LimiterRig rig(matched_mock(limits, 0.02), limits);
    PtuState state;
    constexpr double kFrame = 0.02;
    int frame = 0;
    for (; frame < 50; ++frame) rig.limiter.write(both_axes(CommandMode::Velocity, 1.0, -1.0), at_seconds(kFrame * frame));
    REQUIRE(rig.mock.records().back().command.axes[0].value == 1.0);
    PtuCommand bad;
    bad.axes[0] = {CommandMode::Velocity, kNaN};
    bad.axes[1] = {CommandMode::Position, kInf};
    for (int i = 0; i < 20; ++i, ++frame) {
        rig.limiter.write(bad, at_seconds(kFrame * frame));
        const PtuCommand& sent = rig.mock.records().back().command;
        const double expected = std::max(0.0, 1.0 - 5.0 * kFrame * (i + 1));
        CHECK(sent.axes[0].mode == CommandMode::Velocity);
        CHECK(sent.axes[0].value == Approx(expected).margin(1e-12));
        CHECK(sent.axes[1].mode == CommandMode::Velocity);
        CHECK(sent.axes[1].value == Approx(-expected).margin(1e-12));
    }
    rig.limiter.read(state, at_seconds(kFrame * frame + 0.1));
    CHECK(state.axes[0].velocity_rad_s == 0.0);
    CHECK(state.axes[1].velocity_rad_s == 0.0);
}

TEST_CASE("PtuLimiter clamps position targets, approaches them at max_velocity, and ramps velocity down first", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-1.0, 1.0, 1.0, 5.0);
    LimiterRig rig(matched_mock(limits, 0.0), limits);
    constexpr double kFrame = 0.02;
    int frame = 0;
    for (; frame < 25; ++frame) rig.limiter.write(both_axes(CommandMode::Velocity, -0.5, 0.0), at_seconds(kFrame * frame));
    for (int i = 0; i < 10; ++i, ++frame) rig.limiter.write(both_axes(CommandMode::Position, 5.0, -3.0), at_seconds(kFrame * frame));
    const auto records = rig.mock.records();
    std::size_t first_position = 0;
    while (first_position < records.size() && records[first_position].command.axes[0].mode != CommandMode::Position)
        ++first_position;
    REQUIRE(first_position < records.size());
    for (std::size_t r = 25; r < first_position; ++r) {  // the ramp down, at 5 rad/s² over 0.02 s frames
        INFO("record " << r);
        CHECK(records[r].command.axes[0].mode == CommandMode::Velocity);
        CHECK(records[r].command.axes[0].value == Approx(std::min(0.0, -0.5 + 0.1 * static_cast<double>(r - 24))).margin(1e-12));
    }
    CHECK(records[first_position - 1].command.axes[0].value == 0.0);  // exactly at rest before the move
    CHECK(records[25].command.axes[1].mode == CommandMode::Position);  // tilt was at rest: no ramp
    // The targets passed on advance toward the clamped ones at 1 rad/s (0.02 rad a frame).
    CHECK(records[first_position].command.axes[0].value < -0.2);  // a step from where the axis stands (about -0.28)
    CHECK(records[25].command.axes[1].value == Approx(-0.02).margin(1e-9));
    PtuState state;
    for (; frame < 200; ++frame) {  // reading too, as the frame loop does: the limiter predicts from the reports
        rig.limiter.write(both_axes(CommandMode::Position, 5.0, -3.0), at_seconds(kFrame * frame));
        rig.limiter.read(state, at_seconds(kFrame * frame));
    }
    const auto all = rig.mock.records();
    for (std::size_t r = first_position + 1; r < all.size(); ++r) {
        INFO("record " << r);
        CHECK(all[r].command.axes[0].value - all[r - 1].command.axes[0].value <= 0.02 + 1e-9);
        CHECK(all[r].command.axes[0].value <= 1.0);  // clamped
        CHECK(all[r].command.axes[1].value >= -1.0);
    }
    CHECK(all.back().command.axes[0].value == 1.0);
    CHECK(all.back().command.axes[1].value == -1.0);
    rig.limiter.read(state, at_seconds(10.0));
    CHECK(state.axes[0].position_rad == Approx(1.0).margin(1e-12));
    CHECK(state.axes[1].position_rad == Approx(-1.0).margin(1e-12));
}

TEST_CASE("PtuLimiter keeps a faster unit's position move to max_velocity, and to a limit lowered during it", "[limiter]") {
    PtuLimits limits = symmetric_limits(-3.0, 3.0, 1.0, 5.0);
    MockPtuConfig drive = matched_mock(limits, 0.0);
    drive.max_velocity_rad_s = 3.0;  // its own position moves would go at 3 rad/s
    LimiterRig rig(drive, limits);
    constexpr double kFrame = 0.02;
    PtuState state;
    double arrived_at = -1.0;
    std::vector<double> positions;
    for (int frame = 0; frame < 400 && arrived_at < 0.0; ++frame) {
        const double t = kFrame * frame;
        if (frame == 50) {  // at 1 s, about 1 rad along: a reload halves the limit
            limits.axes[0].max_velocity_rad_s = 0.5;
            rig.limiter.set_limits(limits);
        }
        rig.limiter.write(both_axes(CommandMode::Position, 2.5, 0.0), at_seconds(t));
        rig.limiter.read(state, at_seconds(t + kFrame));
        positions.push_back(state.axes[0].position_rad);
        if (std::abs(state.axes[0].position_rad - 2.5) < 1e-6) arrived_at = t + kFrame;
    }
    // 1 rad at 1 rad/s, then 1.5 rad at 0.5 rad/s: 4 s (the unit alone: under 1 s).
    CHECK(arrived_at > 4.0);
    CHECK(arrived_at < 4.3);
    // Over every half second before the change, and from 1 s after it (the unit first closes the
    // 0.1 rad it lagged behind the targets at 1 rad/s).
    for (std::size_t k = 25; k < positions.size(); ++k) {
        if (k > 50 && k < 125) continue;
        const double speed = (positions[k] - positions[k - 25]) / (25 * kFrame);
        INFO("frame " << k);
        CHECK(speed <= (k <= 50 ? 1.0 : 0.5) * 1.02);  // chasing each target with its own profile, about 1 % over
    }
}

TEST_CASE("PtuLimiter holds an axis still until the unit reports it ready, and after a fault", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-1.0, 1.0, 1.0, 5.0);
    rays::test::ManualClock clock;
    MockPtu mock(matched_mock(limits, 0.0), clock);
    PtuLimiter limiter(mock);
    REQUIRE(limiter.configure().ok);
    REQUIRE(limiter.activate().ok);
    PtuState state;
    REQUIRE(limiter.read(state, at_seconds(0.0)).ok);
    limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.1));  // no limits yet
    CHECK(mock.records().back().command.axes[0].value == 0.0);
    limiter.set_limits(limits);
    limiter.deactivate();
    REQUIRE(limiter.activate().ok);
    limiter.write(both_axes(CommandMode::Position, 0.5, 0.5), at_seconds(0.2));  // no report since activate
    CHECK(mock.records().back().command.axes[0].mode == CommandMode::Velocity);
    CHECK(mock.records().back().command.axes[0].value == 0.0);
    REQUIRE(limiter.read(state, at_seconds(0.3)).ok);
    limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.4));
    CHECK(mock.records().back().command.axes[0].value == Approx(0.5));  // 5 rad/s² for 0.1 s

    clock.set_seconds(0.5);
    mock.inject_fault(Axis::Pan, "encoder");
    REQUIRE(limiter.read(state, at_seconds(0.5)).ok);
    CHECK_FALSE(limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.6)).ok);
    mock.clear_fault();
    limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.7));
    CHECK(mock.records().back().command.axes[0].value == 0.0);
    CHECK(mock.records().back().command.axes[1].value == 0.0);  // the failed write held both
    REQUIRE(limiter.read(state, at_seconds(0.8)).ok);
    limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.9));
    CHECK(mock.records().back().command.axes[0].value == Approx(0.5));
}

TEST_CASE("PtuLimiter holds the axes still while more commands are in flight than it remembers", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-10.0, 10.0, 1.0, 5.0);
    LimiterRig rig(matched_mock(limits, 0.0), limits);
    constexpr double kFrame = 0.01;
    int frame = 1;
    for (; frame <= static_cast<int>(PtuLimiter::kInFlightCapacity) + 1; ++frame)
        rig.limiter.write(both_axes(CommandMode::Velocity, 0.5, 0.5), at_seconds(kFrame * frame));
    CHECK(rig.mock.records().back().command.axes[0].value == 0.5);  // no read since time 0, all still known
    rig.limiter.write(both_axes(CommandMode::Velocity, 0.5, 0.5), at_seconds(kFrame * frame++));
    CHECK(rig.mock.records().back().command.axes[0].value == 0.0);  // the oldest was forgotten
    PtuState state;
    REQUIRE(rig.limiter.read(state, at_seconds(kFrame * frame)).ok);
    rig.limiter.write(both_axes(CommandMode::Velocity, 0.5, 0.5), at_seconds(kFrame * frame));
    CHECK(rig.mock.records().back().command.axes[0].value == Approx(5.0 * kFrame));
}

TEST_CASE("PtuLimiter stop() commands zero at once and does not refresh staleness", "[limiter]") {
    const PtuLimits limits = symmetric_limits(-10.0, 10.0, 1.0, 5.0);
    LimiterRig rig(matched_mock(limits, 0.0), limits);
    CHECK(rig.limiter.command_stale(at_seconds(0.0), 1.0));  // never written
    for (int i = 0; i < 20; ++i) rig.limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(0.05 * i));
    CHECK_FALSE(rig.limiter.command_stale(at_seconds(1.2), 0.5));
    CHECK(rig.limiter.command_stale(at_seconds(1.5), 0.5));
    REQUIRE(rig.limiter.stop(at_seconds(1.5)).ok);
    CHECK(rig.mock.records().back().command.axes[0].value == 0.0);
    CHECK(rig.mock.records().back().command.axes[1].value == 0.0);
    CHECK(rig.limiter.command_stale(at_seconds(1.5), 0.5));
    // The next command slews up from zero again.
    rig.limiter.write(both_axes(CommandMode::Velocity, 1.0, 1.0), at_seconds(1.55));
    CHECK(rig.mock.records().back().command.axes[0].value == Approx(0.25));
}

TEST_CASE("PtuLimiter passes the lifecycle through to its driver", "[limiter]") {
    rays::test::ManualClock clock;
    MockPtu mock(MockPtuConfig{}, clock);
    PtuLimiter limiter(mock);
    CHECK(std::string(limiter.name()) == "mock");
    REQUIRE(limiter.configure().ok);
    CHECK(mock.configured());
    REQUIRE(limiter.activate().ok);
    CHECK(mock.active());
    limiter.deactivate();
    CHECK_FALSE(mock.active());
    CHECK(mock.lifecycle_calls().size() == 3);
}
