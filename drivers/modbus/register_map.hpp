// SPDX-License-Identifier: Apache-2.0
// The resolved register map of a pan/tilt unit on Modbus: per axis the slave, the registers and how
// values are encoded; built from a preset (a drive family's published map) or the custom keys.
// Shared by the driver and by tools/ptu-sim, so both read one definition.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "drivers/modbus/modbus_settings.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

struct AxisRegisters {
    int slave = 1;
    int velocity = -1;  // -1: absent
    int position = -1;
    int actual_position = -1;
    int status = -1;
    std::uint16_t fault_mask = 0;
    int enable = -1;
    std::uint16_t enable_value = 1;
    std::uint16_t disable_value = 0;
    int trigger = -1;
    std::uint16_t trigger_value = 1;
    int mode = -1;  // written mode_value once after connecting (e.g. "velocity mode")
    std::uint16_t mode_value = 0;
    int velocity_bits = 16;
    int position_bits = 32;
    bool low_word_first = false;
    double velocity_counts_per_rad_s = 1000.0;
    double position_counts_per_rad = 10000.0;
};

struct RegisterMap {
    std::array<AxisRegisters, kAxes> axes{};
    int watchdog_register = -1;  // per slave
    double watchdog_ms_per_count = 1.0;
};

// Builds the map `settings` describe; nullopt with `error` for an unknown preset or a map that
// cannot drive the unit (no target register, a bad slave id, 32 bit with a register at 65535, ...).
std::optional<RegisterMap> build_register_map(const ModbusSettings& settings, std::string& error);

inline int register_count(int bits) { return bits == 32 ? 2 : 1; }
// Two's complement in `bits` (16 or 32) over one or two registers, high word first unless
// low_word_first (Modbus itself orders only the bytes within a register: big-endian, spec 4.2).
void encode_counts(std::int32_t counts, int bits, bool low_word_first, std::uint16_t* registers);
std::int32_t decode_counts(const std::uint16_t* registers, int bits, bool low_word_first);
// value × scale rounded and held within the axis's bit width; non-finite gives 0.
std::int32_t to_counts(double value, double counts_per_unit, int bits);

}  // namespace rays::ptu
