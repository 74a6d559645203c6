// SPDX-License-Identifier: Apache-2.0
#include "drivers/modbus/register_map.hpp"

#include <cmath>
#include <limits>

#include "drivers/modbus/presets.hpp"

namespace rays::ptu {
namespace {

const char* const kAxisNames[kAxes] = {"pan", "tilt"};

AxisRegisters custom_axis(const ModbusAxisSettings& s) {
    AxisRegisters axis;
    axis.slave = s.slave;
    axis.velocity = s.velocity_register;
    axis.position = s.position_register;
    axis.actual_position = s.actual_position_register;
    axis.status = s.status_register;
    axis.fault_mask = static_cast<std::uint16_t>(s.fault_mask);
    axis.enable = s.enable_register;
    axis.enable_value = static_cast<std::uint16_t>(s.enable_value);
    axis.disable_value = static_cast<std::uint16_t>(s.disable_value);
    axis.trigger = s.trigger_register;
    axis.trigger_value = static_cast<std::uint16_t>(s.trigger_value);
    axis.velocity_bits = s.velocity_bits;
    axis.position_bits = s.position_bits;
    axis.low_word_first = s.word_order == "low_first";
    return axis;
}

bool fits(int reg, int bits) { return reg < 0 || reg + register_count(bits) - 1 <= 0xFFFF; }

std::string check_axis(const AxisRegisters& axis, const char* name) {
    const std::string n = name;
    if (axis.slave < 1 || axis.slave > 247) return n + ": slave id must be 1..247 (modbus." + n + "_slave)";
    if (axis.velocity < 0 && axis.position < 0)
        return n + ": the map has neither a velocity nor a position target register";
    for (int bits : {axis.velocity_bits, axis.position_bits})
        if (bits != 16 && bits != 32) return n + ": register widths must be 16 or 32 bit";
    if (!fits(axis.velocity, axis.velocity_bits) || !fits(axis.position, axis.position_bits) ||
        !fits(axis.actual_position, axis.position_bits))
        return n + ": a 32 bit value cannot start at register 65535";
    if (axis.velocity >= 0 && (axis.velocity_counts_per_rad_s == 0.0 || !std::isfinite(axis.velocity_counts_per_rad_s)))
        return n + ": velocity_counts_per_rad_s must not be 0";
    if ((axis.position >= 0 || axis.actual_position >= 0) && axis.position_counts_per_rad == 0.0)
        return n + ": position_counts_per_rad must not be 0";
    return {};
}

}  // namespace

std::optional<RegisterMap> build_register_map(const ModbusSettings& settings, std::string& error) {
    RegisterMap map;
    if (settings.preset == "custom") {
        map.axes[0] = custom_axis(settings.pan);
        map.axes[1] = custom_axis(settings.tilt);
        map.watchdog_register = settings.comm_watchdog_register;
        map.watchdog_ms_per_count = settings.comm_watchdog_ms_per_count;
    } else if (auto preset = find_preset(settings.preset)) {
        map = preset->map;
    } else {
        error = "modbus.preset: unknown preset " + settings.preset;
        return std::nullopt;
    }
    const ModbusAxisSettings* keys[kAxes] = {&settings.pan, &settings.tilt};
    for (std::size_t i = 0; i < kAxes; ++i) {
        AxisRegisters& axis = map.axes[i];
        if (keys[i]->slave != 0) axis.slave = keys[i]->slave;
        axis.velocity_counts_per_rad_s = keys[i]->velocity_counts_per_rad_s;
        axis.position_counts_per_rad = keys[i]->position_counts_per_rad;
        std::string problem = check_axis(axis, kAxisNames[i]);
        if (!problem.empty()) {
            error = "modbus: " + problem;
            return std::nullopt;
        }
    }
    return map;
}

void encode_counts(std::int32_t counts, int bits, bool low_word_first, std::uint16_t* registers) {
    const auto raw = static_cast<std::uint32_t>(counts);
    if (bits == 16) {
        registers[0] = static_cast<std::uint16_t>(raw & 0xFFFFu);
        return;
    }
    const auto high = static_cast<std::uint16_t>(raw >> 16), low = static_cast<std::uint16_t>(raw & 0xFFFFu);
    registers[0] = low_word_first ? low : high;
    registers[1] = low_word_first ? high : low;
}

std::int32_t decode_counts(const std::uint16_t* registers, int bits, bool low_word_first) {
    if (bits == 16) return static_cast<std::int16_t>(registers[0]);
    const std::uint32_t high = low_word_first ? registers[1] : registers[0];
    const std::uint32_t low = low_word_first ? registers[0] : registers[1];
    return static_cast<std::int32_t>((high << 16) | low);
}

std::int32_t to_counts(double value, double counts_per_unit, int bits) {
    const double counts = std::round(value * counts_per_unit);
    if (!std::isfinite(counts)) return 0;
    const double limit = bits == 16 ? 32767.0 : 2147483647.0;
    return static_cast<std::int32_t>(std::fmax(-limit, std::fmin(limit, counts)));
}

}  // namespace rays::ptu
