// SPDX-License-Identifier: Apache-2.0
// GpiodLines against a real GPIO character device, and the [gpio]/[pwm] parameter tables.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "config/config_engine.hpp"
#include "drivers/gpio/gpio_params.hpp"
#include "drivers/gpio/gpiod_lines.hpp"
#include "drivers/gpio/pwm_params.hpp"
#include "support/skip.hpp"

using namespace rays;
using namespace rays::gpio;

TEST_CASE("GpiodLines: a missing chip is a clear error", "[gpio][gpiod]") {
    GpiodLines lines;
    LineRequest request;
    request.chip = "/dev/rays-no-such-gpiochip";
    const ptu::DriverStatus status = lines.open(request);
    CHECK_FALSE(status.ok);
    CHECK(std::string(status.what()).find("cannot open chip") != std::string::npos);
}

TEST_CASE("GpiodLines: requests, sets and reads lines of /dev/gpiochip0", "[gpio][gpiod]") {
    if (!std::filesystem::exists("/dev/gpiochip0")) test::skip("no /dev/gpiochip0 on this machine (no GPIO kernel support)");
    GpiodLines lines;
    LineRequest request;
    request.chip = "gpiochip0";
    request.outputs = {{0, false}};
    const ptu::DriverStatus status = lines.open(request);
    if (!status.ok) test::skip(std::string("line 0 of gpiochip0 cannot be requested here: ") + status.what());
    TimePoint before = MonoClock::now(), at;
    CHECK(lines.set(0, true, at));
    CHECK(at >= before);
    CHECK(lines.set(0, false, at));
}

TEST_CASE("[gpio] and [pwm] load from an INI file with file:line errors", "[gpio][config]") {
    const std::string path = (std::filesystem::temp_directory_path() / ("rays-gpio-" + std::to_string(::getpid()) + ".ini")).string();
    std::ofstream(path) << "[gpio]\nchip = gpiochip1\npan_step_line = 17\npan_dir_line = 27\ntilt_step_line = 22\n"
                           "tilt_dir_line = 23\nenable_line = 24\npan_home_switch = min\npan_limit_min_line = 5\n";
    GpioSettings gpio;
    CHECK_FALSE(config::load_ini(path, gpio_params(), gpio).has_value());
    CHECK(gpio.chip == "gpiochip1");
    CHECK(gpio.pan_dir_line == 27);
    CHECK(gpio.pan_home_switch == "min");
    std::ofstream(path) << "[gpio]\nmax_step_rate_hz = 50000\n";
    CHECK(config::load_ini(path, gpio_params(), gpio).has_value());  // above the measured maximum
    std::ofstream(path) << "[pwm]\npan_chip = 1\npan_min_pulse_us = 2100\n";
    PwmSettings pwm;
    CHECK(config::load_ini(path, pwm_params(), pwm).has_value());  // min pulse above max pulse
    std::ofstream(path) << "[pwm]\ntilt_channel = 2\nperiod_ms = 20\n";
    CHECK_FALSE(config::load_ini(path, pwm_params(), pwm).has_value());
    CHECK(pwm.tilt_channel == 2);
    std::filesystem::remove(path);
    CHECK(gpio_params().sections().size() == 1);
    CHECK(pwm_params().sections().size() == 1);
}
