// SPDX-License-Identifier: Apache-2.0
// pwm-servo against FakePwmChannel (every write with its time) and SysfsPwmChannel against a
// temporary directory laid out like /sys/class/pwm.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <thread>
#include <vector>

#include "drivers/gpio/fake_pwm_channel.hpp"
#include "drivers/gpio/pwm_servo.hpp"
#include "drivers/gpio/sysfs_pwm_channel.hpp"

using namespace rays;
using namespace rays::gpio;
using ptu::CommandMode;

namespace {

double deg(double d) { return d * std::numbers::pi / 180.0; }

ptu::PtuCommand both(CommandMode mode, double pan, double tilt) {
    ptu::PtuCommand c;
    c.axes[0] = {mode, pan};
    c.axes[1] = {mode, tilt};
    return c;
}

struct ServoRig {
    explicit ServoRig(const PwmSettings& settings = PwmSettings{}) {
        std::string error;
        driver = make_pwm_servo_driver(settings, clock, pan, tilt, error);
        REQUIRE(driver != nullptr);
        REQUIRE(driver->configure().ok);
        REQUIRE(driver->activate().ok);
    }
    void drive(const ptu::PtuCommand& command, double seconds) {
        const auto end = MonoClock::now() + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds));
        while (MonoClock::now() < end) {
            driver->write(command, clock.now());
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    SteadyClock clock;
    FakePwmChannel pan, tilt;
    std::unique_ptr<PwmServo> driver;
};

PwmSettings fast_moves() {
    PwmSettings settings;
    settings.move_speed_deg_s = 10000.0;  // a position command's angle at once
    return settings;
}

}  // namespace

TEST_CASE("pwm-servo: duty cycles follow the commanded angles, clamped to the range", "[pwm]") {
    ServoRig rig(fast_moves());  // 1000–2000 µs over −90°..90°, 20 ms
    CHECK(rig.pan.period_ns() == 20000000);
    CHECK(rig.pan.enabled());
    CHECK(rig.pan.duty_ns() == 1500000);  // start angle 0°
    rig.drive(both(CommandMode::Position, deg(45.0), deg(-30.0)), 0.05);
    CHECK(rig.pan.duty_ns() == 1750000);
    CHECK(rig.tilt.duty_ns() == std::lround(1500000 - 30.0 / 90.0 * 500000));
    rig.drive(both(CommandMode::Position, deg(120.0), deg(-200.0)), 0.05);
    CHECK(rig.pan.duty_ns() == 2000000);
    CHECK(rig.tilt.duty_ns() == 1000000);
    for (const PwmWrite& write : rig.pan.writes())
        if (write.file == PwmWrite::File::Duty) CHECK((write.value >= 1000000 && write.value <= 2000000));
}

TEST_CASE("pwm-servo: velocity integrates, stop holds the estimated position, read reports the estimate", "[pwm]") {
    ServoRig rig;
    rig.drive(both(CommandMode::Velocity, deg(30.0), 0.0), 1.0);
    ptu::PtuState state;
    REQUIRE(rig.driver->read(state, rig.clock.now()).ok);
    CHECK(state.axes[0].position_rad == Approx(deg(30.0)).margin(deg(2.0)));
    CHECK(state.axes[0].homed);
    const long moving_duty = rig.pan.duty_ns();
    CHECK(moving_duty == Approx(1500000 + 30.0 / 90.0 * 500000).margin(12000));
    rig.drive(ptu::PtuCommand::stop(), 0.3);
    const long held = rig.pan.duty_ns();
    CHECK(std::abs(held - moving_duty) < 6000);  // at most about one frame of travel on
    rig.drive(ptu::PtuCommand::stop(), 0.3);
    CHECK(rig.pan.duty_ns() == held);
    REQUIRE(rig.driver->read(state, rig.clock.now()).ok);
    CHECK(state.axes[0].velocity_rad_s == Approx(0.0));
}

TEST_CASE("pwm-servo: stale commands hold, deactivate disables only when configured", "[pwm]") {
    PwmSettings settings = fast_moves();
    settings.pan_speed_deg_s = 60.0;
    ServoRig rig(settings);
    rig.drive(both(CommandMode::Position, deg(80.0), 0.0), 0.05);  // takes 1.3 s at 60°/s
    std::this_thread::sleep_for(std::chrono::milliseconds(700));   // stale after 0.5 s
    const long held = rig.pan.duty_ns();
    CHECK(static_cast<double>(held) < 1500000 + 80.0 / 90.0 * 500000 - 20000);  // not the far target: where the servo was
    CHECK(held > 1500000 + 20000);
    CHECK(rig.driver->report().holding);
    rig.driver->deactivate();
    CHECK(rig.pan.enabled());  // disable_on_deactivate = false: it holds

    settings.disable_on_deactivate = true;
    ServoRig limp(settings);
    limp.driver->deactivate();
    CHECK_FALSE(limp.pan.enabled());
    CHECK_FALSE(limp.tilt.enabled());
}

TEST_CASE("pwm-servo: a position move slews at the move speed, not at the servo's rated speed", "[pwm]") {
    PwmSettings settings;  // rated 300°/s
    settings.move_speed_deg_s = 45.0;
    ServoRig rig(settings);
    const auto duty_of = [](double angle_deg) { return 1500000 + angle_deg / 90.0 * 500000; };
    rig.drive(both(CommandMode::Position, deg(40.0), 0.0), 0.5);
    const double halfway = static_cast<double>(rig.pan.duty_ns());
    CHECK(halfway > duty_of(15.0));  // 22.5° after 0.5 s at 45°/s
    CHECK(halfway < duty_of(30.0));  // at once at the rated speed
    rig.drive(both(CommandMode::Position, deg(40.0), 0.0), 0.7);
    CHECK(rig.pan.duty_ns() == std::lround(duty_of(40.0)));
    CHECK(rig.tilt.duty_ns() == std::lround(duty_of(0.0)));
    // No stretch of 0.1 s or more in the duty cycles written is faster than the move speed.
    std::vector<PwmWrite> duties;
    for (const PwmWrite& write : rig.pan.writes())
        if (write.file == PwmWrite::File::Duty) duties.push_back(write);
    REQUIRE(duties.size() > 20);
    double fastest_deg_s = 0.0;
    for (std::size_t i = 0, j = 0; j < duties.size(); ++j) {
        while (i + 1 < j && std::chrono::duration<double>(duties[j].time - duties[i + 1].time).count() >= 0.1) ++i;
        const double span_s = std::chrono::duration<double>(duties[j].time - duties[i].time).count();
        if (span_s >= 0.1)
            fastest_deg_s = std::max(fastest_deg_s, static_cast<double>(std::abs(duties[j].value - duties[i].value)) / 500000.0 * 90.0 / span_s);
    }
    CHECK(fastest_deg_s > 30.0);
    CHECK(fastest_deg_s < 45.0 * 1.15);  // one write's step over 0.1 s
}

TEST_CASE("pwm-servo: a failed write faults, holds the other axis and recovers after reopening", "[pwm]") {
    ServoRig rig(fast_moves());
    rig.drive(both(CommandMode::Position, deg(10.0), deg(10.0)), 0.05);
    rig.pan.set_failing(true);
    rig.drive(both(CommandMode::Position, deg(20.0), deg(20.0)), 0.05);
    ptu::PtuState state;
    const ptu::DriverStatus status = rig.driver->read(state, rig.clock.now());
    REQUIRE_FALSE(status.ok);
    CHECK(state.axes[0].fault);
    rig.pan.set_failing(false);
    rig.drive(both(CommandMode::Position, deg(20.0), deg(20.0)), 0.8);
    CHECK(rig.driver->read(state, rig.clock.now()).ok);
    CHECK(rig.pan.duty_ns() == std::lround(1500000 + 20.0 / 90.0 * 500000));
}

TEST_CASE("pwm-servo: the factory refuses impossible ranges", "[pwm]") {
    SteadyClock clock;
    FakePwmChannel pan, tilt;
    std::string error;
    PwmSettings s;
    s.pan_max_pulse_us = 900.0;
    CHECK(make_pwm_servo_driver(s, clock, pan, tilt, error) == nullptr);
    s = PwmSettings{};
    s.period_ms = 2.0;
    CHECK(make_pwm_servo_driver(s, clock, pan, tilt, error) == nullptr);
    s = PwmSettings{};
    s.tilt_channel = s.pan_channel;
    CHECK(make_pwm_servo_driver(s, clock, pan, tilt, error) == nullptr);
}

TEST_CASE("SysfsPwmChannel: exports, writes period, duty_cycle and enable as sysfs files", "[pwm]") {
    namespace fs = std::filesystem;
    const fs::path root = fs::temp_directory_path() / ("rays-pwm-" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "pwmchip0" / "pwm1");
    for (const char* file : {"period", "duty_cycle", "enable"}) std::ofstream(root / "pwmchip0" / "pwm1" / file) << "0\n";
    std::ofstream(root / "pwmchip0" / "export") << "";
    auto read_number = [&](const char* file) {
        std::ifstream in(root / "pwmchip0" / "pwm1" / file);
        long value = -1;
        in >> value;
        return value;
    };
    SysfsPwmChannel channel(root.string(), 0, 1);
    REQUIRE(channel.open(20000000).ok);
    CHECK(read_number("period") == 20000000);
    TimePoint at;
    REQUIRE(channel.set_duty_ns(1500000, at));
    CHECK(read_number("duty_cycle") == 1500000);
    REQUIRE(channel.set_enabled(true, at));
    CHECK(read_number("enable") == 1);
    SysfsPwmChannel missing(root.string(), 3, 0);
    const ptu::DriverStatus status = missing.open(20000000);
    CHECK_FALSE(status.ok);
    CHECK(std::strstr(status.what(), "export") != nullptr);
    fs::remove_all(root);
}
