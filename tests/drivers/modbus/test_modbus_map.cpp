// SPDX-License-Identifier: Apache-2.0
// Register maps: presets resolve, encodings round-trip in both word orders, bad maps are refused.
#include <catch2/catch.hpp>

#include "drivers/modbus/modbus_ptu.hpp"
#include "drivers/modbus/presets.hpp"

using namespace rays::ptu;

TEST_CASE("32-bit values are split into words in the configured order", "[modbus]") {
    std::uint16_t regs[2];
    encode_counts(-2, 32, false, regs);
    CHECK(regs[0] == 0xFFFF);
    CHECK(regs[1] == 0xFFFE);
    CHECK(decode_counts(regs, 32, false) == -2);
    encode_counts(0x12345678, 32, true, regs);
    CHECK(regs[0] == 0x5678);
    CHECK(regs[1] == 0x1234);
    CHECK(decode_counts(regs, 32, true) == 0x12345678);
    encode_counts(-20, 16, false, regs);
    CHECK(regs[0] == 0xFFEC);
    CHECK(decode_counts(regs, 16, false) == -20);
    CHECK(to_counts(1e9, 1.0, 16) == 32767);
    CHECK(to_counts(0.0 / 0.0 * 1.0, 1.0, 32) == 0);
}

TEST_CASE("presets and the custom map resolve, invalid combinations are refused", "[modbus]") {
    rays::SteadyClock clock;
    std::string error;
    ModbusSettings settings;
    settings.preset = "leadshine-eld2";
    REQUIRE(make_modbus_driver(settings, clock, error) != nullptr);
    settings.preset = "uumotor-svd48v";
    REQUIRE(make_modbus_driver(settings, clock, error) != nullptr);
    settings.preset = "nonesuch";
    CHECK(make_modbus_driver(settings, clock, error) == nullptr);
    CHECK(error.find("unknown preset") != std::string::npos);
    settings.preset = "custom";  // no slave ids, no registers
    CHECK(make_modbus_driver(settings, clock, error) == nullptr);
    CHECK(error.find("slave id") != std::string::npos);
    settings.pan.slave = 1;
    settings.tilt.slave = 2;
    CHECK(make_modbus_driver(settings, clock, error) == nullptr);
    CHECK(error.find("neither a velocity nor a position") != std::string::npos);
    settings.pan.velocity_register = settings.tilt.velocity_register = 0;
    settings.tilt.position_register = 65535;
    CHECK(make_modbus_driver(settings, clock, error) == nullptr);
    settings.tilt.position_register = -1;
    CHECK(make_modbus_driver(settings, clock, error) != nullptr);
    settings.transport = "rtu";
    settings.device.clear();
    CHECK(make_modbus_driver(settings, clock, error) == nullptr);
}

TEST_CASE("configure fails with a clear message when nothing answers", "[modbus]") {
    rays::SteadyClock clock;
    std::string error;
    ModbusSettings settings;
    settings.port = 1;  // nothing listens on port 1 of loopback
    settings.pan = {};
    settings.pan.slave = 1;
    settings.pan.velocity_register = 0;
    settings.tilt = settings.pan;
    auto driver = make_modbus_driver(settings, clock, error);
    REQUIRE(driver);
    const DriverStatus status = driver->configure();
    CHECK_FALSE(status.ok);
    CHECK(std::string(status.what()).find("cannot connect to 127.0.0.1:1") != std::string::npos);
    CHECK_FALSE(driver->write(PtuCommand::stop(), clock.now()).ok);
}
