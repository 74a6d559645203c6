// SPDX-License-Identifier: Apache-2.0
// The Modbus driver end to end against tools/ptu-sim (real libmodbus on both sides), over loopback
// TCP and over a pty pair (RTU). Every check reads what the simulated unit received (its CSV
// record) or how its axes move, never the driver's own account.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstring>

#include "modbus_rig.hpp"
#include "support/skip.hpp"

using namespace rays;
using namespace rays::test;

namespace {

// Writes `command` every 20 ms for `seconds`, as the frame loop would; the last status.
ptu::DriverStatus drive(ptu::PtuDriver& driver, const ptu::PtuCommand& command, double seconds) {
    ptu::DriverStatus status;
    const double end = monotonic_seconds() + seconds;
    SteadyClock clock;
    while (monotonic_seconds() < end) {
        status = driver.write(command, clock.now());
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return status;
}

ptu::DriverStatus read_status(ptu::PtuDriver& driver) {
    ptu::PtuState state;
    return driver.read(state, MonoClock::now());
}

bool moving(SimProcess& sim) {
    const SimProcess::State s = sim.state();
    return std::abs(s.velocity[0]) > 0.1 && std::abs(s.velocity[1]) > 0.1;
}
bool stopped(SimProcess& sim) {
    const SimProcess::State s = sim.state();
    return s.velocity[0] == 0.0 && s.velocity[1] == 0.0;
}

// Writes `command` until the unit moves, however long a loaded machine takes; true when it does.
bool drive_until_moving(Rig& rig, const ptu::PtuCommand& command) {
    return eventually([&] {
        rig.driver->write(command, rig.clock.now());
        return moving(*rig.sim);
    });
}

// A zero velocity (or a drive-side stop) received for both axes at or after `after_s`.
bool stop_received(const std::vector<Received>& rows, double after_s) {
    bool zero[2] = {false, false};
    for (const Received& r : rows) {
        if (r.time_s < after_s) continue;
        if (r.note == "watchdog_stop") return true;
        if (r.slave >= 1 && r.slave <= 2 && r.address == 1 && r.value == 0) {
            std::int32_t v = -1;
            if (last_value32(rows, r.slave, 0, r.time_s - 1e-6, v) && v == 0) zero[r.slave - 1] = true;
        }
    }
    return zero[0] && zero[1];
}

void move_and_check(Rig& rig) {
    const bool up = rig.up();
    INFO(rig.error);
    REQUIRE(up);
    const double start = monotonic_seconds();
    CHECK(drive(*rig.driver, velocities(0.5, -0.25), 0.4).ok);
    ptu::PtuState state;
    CHECK(eventually([&] {  // moving, and far enough for the driver to read the travel back
        rig.driver->write(velocities(0.5, -0.25), rig.clock.now());
        return moving(*rig.sim) && rig.driver->read(state, MonoClock::now()).ok && state.axes[0].position_rad > 0.05 &&
               state.axes[1].position_rad < -0.02;
    }));
    std::int32_t pan = 0, tilt = 0;
    const auto rows = rig.received();
    REQUIRE(last_value32(rows, 1, 0, start, pan));
    REQUIRE(last_value32(rows, 2, 0, start, tilt));
    CHECK(pan == 500);  // 0.5 rad/s × 1000 counts per rad/s
    CHECK(tilt == -250);
    CHECK(state.axes[0].enabled);
}

}  // namespace

TEST_CASE("modbus tcp: commands reach the unit and move it", "[modbus]") {
    Rig rig("tcp_move", "tcp", custom_map_ini());
    move_and_check(rig);
    // The unit received the watchdog time and the enables.
    bool watchdog = false, enabled = false;
    for (const Received& r : rig.received()) {
        watchdog = watchdog || (r.address == 100 && r.value == 300);
        enabled = enabled || (r.address == 30 && r.value == 1);
    }
    CHECK(watchdog);
    CHECK(enabled);
    rig.driver->deactivate();
    CHECK(eventually([&] { return stopped(*rig.sim); }));
}

TEST_CASE("modbus rtu over a pty pair: commands reach the unit and move it", "[modbus]") {
    if (system("command -v socat > /dev/null") != 0) skip("socat is not installed (tools/install-deps installs it)");
    Rig rig("rtu_move", "rtu", custom_map_ini());
    move_and_check(rig);
}

TEST_CASE("modbus preset leadshine-eld2: PR0 velocity mode, speed and trigger per slave", "[modbus]") {
    Rig rig("eld2", "tcp", "preset = leadshine-eld2\npan_velocity_counts_per_rad_s = 100\ntilt_velocity_counts_per_rad_s = 100\n");
    REQUIRE(rig.up());
    CHECK(drive_until_moving(rig, velocities(0.5, 0.3)));
    bool mode[2] = {}, speed[2] = {}, trigger[2] = {};
    for (const Received& r : rig.received()) {
        if (r.slave < 1 || r.slave > 2) continue;
        mode[r.slave - 1] = mode[r.slave - 1] || (r.address == 0x6200 && r.value == 2);
        speed[r.slave - 1] = speed[r.slave - 1] || (r.address == 0x6203 && r.value == (r.slave == 1 ? 50u : 30u));
        trigger[r.slave - 1] = trigger[r.slave - 1] || (r.address == 0x6207 && r.value == 0x10);
    }
    CHECK((mode[0] && mode[1] && speed[0] && speed[1] && trigger[0] && trigger[1]));
}

TEST_CASE("modbus preset uumotor-svd48v: both motors of one slave enabled and driven", "[modbus]") {
    Rig rig("svd48v", "tcp", "preset = uumotor-svd48v\npan_velocity_counts_per_rad_s = 100\ntilt_velocity_counts_per_rad_s = 100\n");
    REQUIRE(rig.up());
    CHECK(drive_until_moving(rig, velocities(0.4, -0.2)));
    bool enable[2] = {}, speed[2] = {};
    for (const Received& r : rig.received()) {
        if (r.slave != 1) continue;
        enable[0] = enable[0] || (r.address == 0x5201 && r.value == 1);
        enable[1] = enable[1] || (r.address == 0x5301 && r.value == 1);
        speed[0] = speed[0] || (r.address == 0x5205 && r.value == 40);
        speed[1] = speed[1] || (r.address == 0x5305 && r.value == 0xFFEC);  // -20 as int16
    }
    CHECK((enable[0] && enable[1] && speed[0] && speed[1]));
    ptu::PtuState state;
    CHECK(eventually([&] {  // the travel read back
        rig.driver->write(velocities(0.4, -0.2), rig.clock.now());
        return rig.driver->read(state, MonoClock::now()).ok && state.axes[0].position_rad > 0.0;
    }));
}

TEST_CASE("modbus faults stop the axes, say so and recover", "[modbus]") {
    struct Case {
        const char* name;
        const char* inject;
        const char* clear;
        const char* message;  // part of the DriverStatus text
    };
    const Case cases[] = {
        {"dropped replies", "drop on", "drop off", "no reply"},
        {"slow replies", "slow 150", "slow 0", "no reply"},
        {"exception code", "exception 4", "exception 0", "exception 4"},
        {"disconnect", "disconnect on", "disconnect off", "modbus"},
        {"drive fault", "fault pan on", "fault pan off", "drive reports a fault"},
    };
    for (const Case& c : cases) {
        SECTION(c.name) {
            Rig rig(std::string("fault_") + std::to_string(&c - cases), "tcp", custom_map_ini());
            REQUIRE(rig.up());
            CHECK(drive(*rig.driver, velocities(0.5, 0.5), 0.3).ok);
            REQUIRE(drive_until_moving(rig, velocities(0.5, 0.5)));
            const double injected = monotonic_seconds();
            rig.sim->send(c.inject);
            ptu::DriverStatus status;
            SteadyClock clock;
            CHECK(eventually([&] {
                rig.driver->write(velocities(0.5, 0.5), clock.now());
                status = read_status(*rig.driver);
                return !status.ok;
            }));
            INFO(status.what());
            CHECK(std::strstr(status.what(), c.message) != nullptr);
            // Stopped: zero velocity received for both axes, or the unit's own watchdog stopped them.
            CHECK(eventually([&] { return stopped(*rig.sim); }));
            if (std::strcmp(c.inject, "drop on") != 0 && std::strcmp(c.inject, "disconnect on") != 0)
                CHECK(stop_received(rig.received(), injected));
            rig.sim->send(c.clear);
            const double cleared = monotonic_seconds();
            CHECK(eventually([&] {
                rig.driver->write(velocities(0.5, 0.5), clock.now());
                return read_status(*rig.driver).ok;
            }));
            CHECK(drive_until_moving(rig, velocities(0.5, 0.5)));
            std::int32_t pan = 0;
            CHECK((last_value32(rig.received(), 1, 0, cleared, pan) && pan == 500));
        }
    }
}

TEST_CASE("modbus: a stale command stream stops the axes", "[modbus]") {
    Rig rig("stale", "tcp", custom_map_ini(0));  // no drive-side watchdog: the driver alone
    REQUIRE(rig.up());
    double last_write = 0;
    REQUIRE(eventually([&] {
        last_write = monotonic_seconds();
        rig.driver->write(velocities(0.5, 0.5), rig.clock.now());
        return moving(*rig.sim);
    }));
    CHECK(eventually([&] { return stopped(*rig.sim); }));
    const double stopped_at = monotonic_seconds();
    CHECK(stop_received(rig.received(), last_write));
    CHECK(stopped_at - last_write > 0.25);  // command_timeout_ms = 300, less the ramp
}

TEST_CASE("modbus: the drive's watchdog stops the axes after the driver is killed", "[modbus]") {
    Rig rig("watchdog", "tcp", custom_map_ini(300));
    REQUIRE(rig.error.empty());
    REQUIRE(rig.sim->ready());
    const pid_t child = fork();
    if (child == 0) {  // the daemon: drives until SIGKILL
        SteadyClock clock;
        std::string error;
        auto driver = ptu::make_modbus_driver(rig.settings, clock, error);
        if (!driver || !driver->configure().ok || !driver->activate().ok) _exit(1);
        for (;;) {
            driver->write(velocities(0.5, 0.5), clock.now());
            usleep(20000);
        }
    }
    REQUIRE(eventually([&] { return moving(*rig.sim); }));
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    const double killed = monotonic_seconds();
    CHECK(eventually([&] { return stopped(*rig.sim); }));
    bool tripped = false;
    for (const Received& r : rig.received()) tripped = tripped || (r.note == "watchdog_stop" && r.time_s >= killed);
    CHECK(tripped);
}
