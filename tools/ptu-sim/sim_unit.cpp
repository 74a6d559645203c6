// SPDX-License-Identifier: Apache-2.0
#include "sim_unit.hpp"

#include <modbus/modbus.h>

#include <chrono>

namespace rays::ptusim {
namespace {

bool covers(int reg, int width, int address, int count) {
    return reg >= 0 && reg + width > address && reg < address + count;
}

ptu::AxisDynamicsConfig dynamics_config() {
    ptu::AxisDynamicsConfig config;
    config.max_velocity_rad_s = 3.0;
    config.max_accel_rad_s2 = 30.0;
    return config;
}

}  // namespace

SimUnit::SimUnit(const ptu::RegisterMap& map, Recorder recorder) : map_(map), recorder_(std::move(recorder)) {
    slaves_ = {map.axes[0].slave, map.axes[1].slave};
    for (std::size_t i = 0; i < 2; ++i)
        if (i == 0 || slaves_[1] != slaves_[0]) mappings_[i] = modbus_mapping_new(0, 0, 0x10000, 0);
    for (std::size_t i = 0; i < ptu::kAxes; ++i) {
        axes_[i] = std::make_unique<Axis>(Axis{ptu::AxisDynamics(dynamics_config()), map.axes[i].enable < 0, false, {}});
    }
}

SimUnit::~SimUnit() {
    for (modbus_mapping_t* mapping : mappings_)
        if (mapping != nullptr) modbus_mapping_free(mapping);
}

bool SimUnit::serves(int slave) const { return slave == slaves_[0] || slave == slaves_[1]; }

modbus_mapping_t* SimUnit::mapping(int slave) {
    if (slave == slaves_[0]) return mappings_[0];
    if (slave == slaves_[1]) return mappings_[1] != nullptr ? mappings_[1] : mappings_[0];
    return nullptr;
}

std::uint16_t* SimUnit::registers(int slave) { return mapping(slave)->tab_registers; }

void SimUnit::request_received(TimePoint now) {
    std::lock_guard lock(mutex_);
    last_request_ = now;
    watchdog_tripped_ = false;
}

void SimUnit::before_reply(int slave, TimePoint now) {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < ptu::kAxes; ++i) {
        const ptu::AxisRegisters& axis = map_.axes[i];
        if (axis.slave != slave) continue;
        Axis& a = *axes_[i];
        a.dynamics.advance(now);
        std::uint16_t* regs = registers(slave);
        if (axis.actual_position >= 0)
            ptu::encode_counts(ptu::to_counts(a.dynamics.position(), axis.position_counts_per_rad, axis.position_bits),
                               axis.position_bits, axis.low_word_first, regs + axis.actual_position);
        if (axis.status >= 0) {
            const bool running = a.dynamics.velocity() != 0.0;
            regs[axis.status] = static_cast<std::uint16_t>((running ? 1u : 0u) | (a.fault ? axis.fault_mask : 0u));
        }
    }
}

void SimUnit::after_write(int slave, int address, int count, TimePoint now) {
    std::lock_guard lock(mutex_);
    std::uint16_t* regs = registers(slave);
    for (int r = address; r < address + count; ++r) recorder_(WriteRecord{now, slave, r, regs[r], ""});
    for (std::size_t i = 0; i < ptu::kAxes; ++i) {
        const ptu::AxisRegisters& axis = map_.axes[i];
        if (axis.slave != slave) continue;
        Axis& a = *axes_[i];
        if (covers(map_.watchdog_register, 1, address, count))
            watchdog_ms_ = regs[map_.watchdog_register] * map_.watchdog_ms_per_count;
        if (covers(axis.enable, 1, address, count)) {
            if (regs[axis.enable] == axis.enable_value) a.enabled = true;
            if (regs[axis.enable] == axis.disable_value) {
                a.enabled = false;
                a.dynamics.halt(now);
            }
        }
        const int vwidth = ptu::register_count(axis.velocity_bits), pwidth = ptu::register_count(axis.position_bits);
        bool target = false;
        if (covers(axis.velocity, vwidth, address, count)) {
            const double counts = ptu::decode_counts(regs + axis.velocity, axis.velocity_bits, axis.low_word_first);
            a.pending = {ptu::CommandMode::Velocity, counts / axis.velocity_counts_per_rad_s};
            target = true;
        }
        if (covers(axis.position, pwidth, address, count)) {
            const double counts = ptu::decode_counts(regs + axis.position, axis.position_bits, axis.low_word_first);
            a.pending = {ptu::CommandMode::Position, counts / axis.position_counts_per_rad};
            target = true;
        }
        const bool triggered = covers(axis.trigger, 1, address, count) && regs[axis.trigger] == axis.trigger_value;
        if ((target && axis.trigger < 0) || triggered) apply(i, a.pending, now);
    }
}

void SimUnit::apply(std::size_t i, const ptu::AxisCommand& command, TimePoint now) {
    Axis& a = *axes_[i];
    if (!a.enabled || a.fault) return;  // a disabled or faulted drive ignores targets
    a.dynamics.command(command, now);
}

void SimUnit::check_watchdog(TimePoint now) {
    std::lock_guard lock(mutex_);
    if (watchdog_ms_ <= 0.0 || watchdog_tripped_ || last_request_ == TimePoint{}) return;
    if (now - last_request_ < std::chrono::duration<double, std::milli>(watchdog_ms_)) return;
    watchdog_tripped_ = true;
    for (std::size_t i = 0; i < ptu::kAxes; ++i) axes_[i]->dynamics.halt(now);
    event("watchdog_stop", -1, now);
}

void SimUnit::set_drive_fault(std::size_t axis, bool fault, TimePoint now) {
    std::lock_guard lock(mutex_);
    axes_[axis]->fault = fault;
    if (fault) axes_[axis]->dynamics.halt(now);
    event(fault ? "drive_fault" : "drive_fault_cleared", static_cast<int>(axis), now);
}

AxisView SimUnit::view(std::size_t axis, TimePoint now) {
    std::lock_guard lock(mutex_);
    Axis& a = *axes_[axis];
    a.dynamics.advance(now);
    return {a.dynamics.position(), a.dynamics.velocity(), a.enabled, a.fault};
}

void SimUnit::event(const char* note, int axis, TimePoint now) { recorder_(WriteRecord{now, -1, axis, 0, note}); }

}  // namespace rays::ptusim
