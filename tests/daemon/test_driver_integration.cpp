// SPDX-License-Identifier: Apache-2.0
// raysd with each real driver family configured only through its INI sections, tracking a replayed
// sequence and moving the simulated unit behind the driver's seam (this machine has no CAN or GPIO):
// the CANopen and ODrive drivers on an in-memory CAN bus with simulated drives, the stepper on
// recording GPIO lines, the RC servos on recording PWM channels. Checked on what the unit received.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <thread>

#include "daemon/daemon.hpp"
#include "daemon/daemon_params.hpp"
#include "daemon_process.hpp"
#include "drivers/can/canopen/canopen_driver.hpp"
#include "drivers/can/odrive/odrive_driver.hpp"
#include "drivers/can/sim/cia402_sim_drive.hpp"
#include "drivers/can/sim/odrive_sim_axis.hpp"
#include "drivers/can/sim/sim_bus_host.hpp"
#include "drivers/gpio/fake_gpio_lines.hpp"
#include "drivers/gpio/fake_pwm_channel.hpp"
#include "drivers/gpio/gpio_stepper.hpp"
#include "drivers/gpio/pwm_servo.hpp"
#include "support/eventually.hpp"

namespace {

using namespace rays;
using namespace rays::daemon;
using namespace std::chrono_literals;

// raysd.ini for a driver: a generated sequence replayed at its rate, and `sections`.
DaemonConfig load_config(const std::string& name, const std::string& sections) {
    std::filesystem::path ini = test::write_replay_config(test::fresh_dir("driver-" + name), sections);
    DaemonConfig config;
    auto error = load_daemon_config(ini.string(), config);
    INFO((error ? error->to_string() : ""));
    REQUIRE_FALSE(error);
    return config;
}

// Runs the daemon with `driver` until `moved` holds (however long a loaded machine takes, within
// kEventTimeout), then stops it; returns its exit status.
int run_daemon(const DaemonConfig& config, std::unique_ptr<ptu::PtuDriver> driver, const std::function<bool()>& moved) {
    block_daemon_signals();
    SteadyClock clock;
    Daemon daemon(config, "", DaemonParts{nullptr, std::move(driver), nullptr}, clock);
    int status = -1;
    std::thread runner([&] { status = daemon.run(); });
    test::eventually(moved);
    daemon.request_stop();
    runner.join();
    return status;
}

}  // namespace

TEST_CASE("driver = canopen: CiA 402 drives on the bus follow the tracker and stop at exit") {
    DaemonConfig config = load_config("canopen", "[ptu]\ndriver = canopen\n\n[canopen]\npan_node_id = 3\ntilt_node_id = 4\n");
    CHECK(config.ptu.driver == "canopen");
    SteadyClock clock;
    can::LoopbackBus bus(clock);
    canopen::Cia402SimConfig pan_config, tilt_config;
    pan_config.node = 3;
    tilt_config.node = 4;
    canopen::Cia402SimDrive pan(pan_config), tilt(tilt_config);
    can::SimBusHost host(bus, {&pan, &tilt});
    std::string error;
    auto driver = canopen::make_canopen_driver(config.canopen, bus.transport_for(bus.add_endpoint()), clock, error);
    REQUIRE(driver);
    auto moved = [&] { return std::abs(pan.position_rad()) + std::abs(tilt.position_rad()) > 0.01; };
    CHECK(run_daemon(config, std::move(driver), [&] { return moved() && pan.received().size() > 100; }) == 0);
    CHECK(moved());
    CHECK(pan.received().size() > 100);  // RPDOs every cycle
    CHECK(test::eventually([&] { return pan.velocity_rad_s() == 0.0 && tilt.velocity_rad_s() == 0.0; }));
}

TEST_CASE("driver = odrive: ODrive axes on the bus follow the tracker and stop at exit") {
    DaemonConfig config = load_config("odrive", "[ptu]\ndriver = odrive\n\n[odrive]\npan_node_id = 5\ntilt_node_id = 6\n");
    SteadyClock clock;
    can::LoopbackBus bus(clock);
    odrive::OdriveSimConfig pan_config, tilt_config;
    pan_config.node = 5;
    tilt_config.node = 6;
    odrive::OdriveSimAxis pan(pan_config), tilt(tilt_config);
    can::SimBusHost host(bus, {&pan, &tilt});
    std::string error;
    auto driver = odrive::make_odrive_driver(config.odrive, bus.transport_for(bus.add_endpoint()), clock, error);
    REQUIRE(driver);
    auto moved = [&] { return std::abs(pan.position_rad()) + std::abs(tilt.position_rad()) > 0.01; };
    CHECK(run_daemon(config, std::move(driver), moved) == 0);
    CHECK(moved());
    CHECK(test::eventually([&] { return pan.velocity_rad_s() == 0.0 && tilt.velocity_rad_s() == 0.0; }));
}

TEST_CASE("driver = gpio-stepper: step and direction edges follow the tracker and stop at exit") {
    DaemonConfig config = load_config(
        "gpio", "[ptu]\ndriver = gpio-stepper\n\n[gpio]\npan_step_line = 0\npan_dir_line = 1\ntilt_step_line = 2\n"
                "tilt_dir_line = 3\nenable_line = 4\n");
    SteadyClock clock;
    gpio::FakeGpioLines lines;
    lines.add_motor(0, 1);
    lines.add_motor(2, 3);
    std::string error;
    auto driver = gpio::make_gpio_stepper_driver(config.gpio, clock, lines, error);
    INFO(error);
    REQUIRE(driver);
    auto turned = [&] { return std::abs(lines.steps(0)) + std::abs(lines.steps(2)) > 20; };
    CHECK(run_daemon(config, std::move(driver), turned) == 0);
    CHECK(turned());  // the motors turned
    std::size_t edges = lines.edge_count();
    std::this_thread::sleep_for(500ms);
    CHECK(lines.edge_count() == edges);  // no step after the daemon stopped
}

TEST_CASE("driver = pwm-servo: servo pulse widths follow the tracker") {
    DaemonConfig config = load_config("pwm", "[ptu]\ndriver = pwm-servo\n\n[pwm]\npan_channel = 0\ntilt_channel = 1\n");
    SteadyClock clock;
    gpio::FakePwmChannel pan, tilt;
    std::string error;
    auto driver = gpio::make_pwm_servo_driver(config.pwm, clock, pan, tilt, error);
    REQUIRE(driver);
    auto moved = [&] { return std::abs(pan.duty_ns() - 1'500'000) + std::abs(tilt.duty_ns() - 1'500'000) > 10'000; };
    CHECK(run_daemon(config, std::move(driver), [&] { return moved() && pan.writes().size() > 10; }) == 0);
    CHECK(moved());  // off centre
    CHECK(pan.writes().size() > 10);
}
