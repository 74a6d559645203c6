// SPDX-License-Identifier: Apache-2.0
// The driver against an independent Modbus implementation (python3-pymodbus), so that a misreading
// of the protocol cannot be mirrored by ptu-sim, which shares the driver's libmodbus and map code.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <fstream>

#include "modbus_rig.hpp"
#include "support/skip.hpp"

using namespace rays;
using namespace rays::test;

TEST_CASE("modbus against pymodbus: the peer decodes our writes, we decode its registers", "[modbus]") {
    if (std::system("/usr/bin/python3 -c 'import pymodbus.server' 2> /dev/null") != 0)
        skip("python3-pymodbus (with python3-serial-asyncio) is not importable by /usr/bin/python3");
    const int port = free_tcp_port();
    const std::string log = scratch_dir() + "/pymodbus.csv";
    SimProcess peer({"/usr/bin/python3", RAYS_PYMODBUS_UNIT, std::to_string(port), log}, false);
    const std::string ini = scratch_dir() + "/pymodbus.ini";
    std::ofstream(ini) << "[modbus]\nport = " << port << "\ntimeout_ms = 200\n"
                       << custom_map_ini(0);
    ptu::ModbusSettings settings;
    REQUIRE_FALSE(config::load_ini(ini, ptu::modbus_params(), settings));
    settings.pan.enable_register = settings.tilt.enable_register = -1;
    SteadyClock clock;
    std::string error;
    auto driver = ptu::make_modbus_driver(settings, clock, error);
    REQUIRE(driver);
    ptu::DriverStatus status;
    REQUIRE(eventually([&] { return (status = driver->configure()).ok; }));
    REQUIRE(driver->activate().ok);
    const double start = monotonic_seconds();
    // Raw words as pymodbus stored them: 500 = 0x0000'01F4, -250 = 0xFFFF'FF06 (high word first);
    // written until its log holds both.
    CHECK(eventually([&] {
        driver->write(velocities(0.5, -0.25), clock.now());
        bool pan = false, tilt = false;
        unsigned last[3][2] = {};
        for (const Received& r : read_record(log)) {
            if (r.time_s < start || r.slave < 1 || r.slave > 2 || r.address > 1) continue;
            last[r.slave][r.address] = r.value;
            pan = pan || (r.slave == 1 && last[1][0] == 0x0000 && last[1][1] == 0x01F4);
            tilt = tilt || (r.slave == 2 && last[2][0] == 0xFFFF && last[2][1] == 0xFF06);
        }
        return pan && tilt;
    }));
    ptu::PtuState state;
    CHECK(eventually([&] { return driver->read(state, clock.now()).ok; }));
    CHECK(state.axes[0].position_rad == Approx(1.2345));  // 12345 counts / 10000
    CHECK(state.axes[1].position_rad == Approx(-0.6789));
    driver->deactivate();
}
