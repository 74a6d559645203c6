// SPDX-License-Identifier: Apache-2.0
// The [modbus] keys: one table from which INI loading, checking and the sample file come.
#include <functional>

#include "drivers/modbus/modbus_settings.hpp"

namespace rays::ptu {
namespace {

using config::ParamKind;
using config::ParamTable;

void add_link(ParamTable<ModbusSettings>& table) {
    table.section("modbus", ParamKind::Capacity, [](ModbusSettings& s) -> auto& { return s; })
        .add_choice("transport", &ModbusSettings::transport, "tcp|rtu", "Modbus TCP or Modbus RTU on a serial line")
        .add("host", &ModbusSettings::host, "tcp: address of the drive or gateway")
        .add("port", &ModbusSettings::port, "", 1, 65535, "tcp: port")
        .add("device", &ModbusSettings::device, "rtu: serial device (RS-485 adapter)")
        .add("baud", &ModbusSettings::baud, "bit/s", 1200, 4000000, "rtu: baud rate")
        .add_choice("parity", &ModbusSettings::parity, "none|even|odd", "rtu: parity")
        .add("stop_bits", &ModbusSettings::stop_bits, "", 1, 2, "rtu: stop bits")
        .add_choice("preset", &ModbusSettings::preset, "custom|leadshine-eld2|uumotor-svd48v",
                    "register map of a drive family; custom: the pan_* and tilt_* register keys")
        .add("timeout_ms", &ModbusSettings::timeout_ms, "ms", 1, 5000, "reply timeout of one request")
        .add("retries", &ModbusSettings::retries, "", 0, 10, "further tries of a request that failed")
        .add("fault_after_failures", &ModbusSettings::fault_after_failures, "", 1, 100,
             "consecutive failed I/O cycles before the axis faults, the other stops and the link is reopened")
        .add("comm_watchdog_ms", &ModbusSettings::comm_watchdog_ms, "ms", 0, 60000,
             "drive-side watchdog: the drive stops after this long without a request (0: off)")
        .add("comm_watchdog_register", &ModbusSettings::comm_watchdog_register, "", -1, 65535,
             "custom map: the drive's communication-timeout register, -1: none")
        .add("comm_watchdog_ms_per_count", &ModbusSettings::comm_watchdog_ms_per_count, "ms", 0.001, 10000,
             "custom map: milliseconds per count of that register")
        .add("command_timeout_ms", &ModbusSettings::command_timeout_ms, "ms", 20, 10000,
             "driver-side: the axes stop when write() was not called for this long")
        .add("poll_ms", &ModbusSettings::poll_ms, "ms", 1, 1000, "I/O cycle: state read at least this often");
}

void add_axis(ParamTable<ModbusSettings>& table, const std::string& axis,
              std::function<ModbusAxisSettings&(ModbusSettings&)> part) {
    const std::string p = axis + "_";
    table.section("modbus", ParamKind::Capacity, part)
        .add(p + "slave", &ModbusAxisSettings::slave, "", 0, 247, axis + ": slave id, 0: the preset's")
        .add(p + "velocity_register", &ModbusAxisSettings::velocity_register, "", -1, 65535,
             axis + " (custom): target velocity register, -1: none")
        .add(p + "position_register", &ModbusAxisSettings::position_register, "", -1, 65535,
             axis + " (custom): target position register, -1: none")
        .add(p + "actual_position_register", &ModbusAxisSettings::actual_position_register, "", -1, 65535,
             axis + " (custom): measured position register, -1: none")
        .add(p + "status_register", &ModbusAxisSettings::status_register, "", -1, 65535,
             axis + " (custom): status register, -1: none")
        .add(p + "fault_mask", &ModbusAxisSettings::fault_mask, "", 0, 65535,
             axis + " (custom): status bits that mean a drive fault")
        .add(p + "enable_register", &ModbusAxisSettings::enable_register, "", -1, 65535,
             axis + " (custom): enable register, -1: none")
        .add(p + "enable_value", &ModbusAxisSettings::enable_value, "", 0, 65535, axis + " (custom): value that enables")
        .add(p + "disable_value", &ModbusAxisSettings::disable_value, "", 0, 65535,
             axis + " (custom): value that disables")
        .add(p + "trigger_register", &ModbusAxisSettings::trigger_register, "", -1, 65535,
             axis + " (custom): register written after each target to start it, -1: none")
        .add(p + "trigger_value", &ModbusAxisSettings::trigger_value, "", 0, 65535, axis + " (custom): trigger value")
        .add(p + "velocity_bits", &ModbusAxisSettings::velocity_bits, "", 16, 32,
             axis + " (custom): velocity target width, 16 or 32 bit")
        .add(p + "position_bits", &ModbusAxisSettings::position_bits, "", 16, 32,
             axis + " (custom): target and actual position width, 16 or 32 bit")
        .add_choice(p + "word_order", &ModbusAxisSettings::word_order, "high_first|low_first",
                    axis + " (custom): 32 bit values: which register comes first")
        .add(p + "velocity_counts_per_rad_s", &ModbusAxisSettings::velocity_counts_per_rad_s, "1/(rad/s)", -1e9, 1e9,
             axis + ": velocity register counts per rad/s at the axis (gearing included; negative reverses)")
        .add(p + "position_counts_per_rad", &ModbusAxisSettings::position_counts_per_rad, "1/rad", -1e12, 1e12,
             axis + ": position register counts per radian at the axis");
}

ParamTable<ModbusSettings> build() {
    ParamTable<ModbusSettings> table;
    add_link(table);
    add_axis(table, "pan", [](ModbusSettings& s) -> ModbusAxisSettings& { return s.pan; });
    add_axis(table, "tilt", [](ModbusSettings& s) -> ModbusAxisSettings& { return s.tilt; });
    return table;
}

}  // namespace

const config::ParamTable<ModbusSettings>& modbus_params() {
    static const config::ParamTable<ModbusSettings> table = build();
    return table;
}

}  // namespace rays::ptu
