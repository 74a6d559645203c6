// SPDX-License-Identifier: Apache-2.0
#include "drivers/modbus/modbus_ptu.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace rays::ptu {
namespace {

using std::chrono::milliseconds;

const char* const kAxisNames[kAxes] = {"pan", "tilt"};
constexpr auto kRefresh = milliseconds(200);  // a target is re-sent this often even when unchanged
constexpr auto kMinBackoff = milliseconds(100);
constexpr auto kMaxBackoff = milliseconds(2000);

bool same(const AxisCommand& a, const AxisCommand& b) { return a.mode == b.mode && a.value == b.value; }

}  // namespace

ModbusPtu::ModbusPtu(const ModbusSettings& settings, const RegisterMap& map, const Clock& clock)
    : settings_(settings), map_(map), clock_(clock), link_(settings) {
    last_read_.status = DriverStatus::failure("modbus: not configured");
}

ModbusPtu::~ModbusPtu() { deactivate(); }

double ModbusPtu::command_latency_s() const {
    // A command waits at most for the request in flight, then travels one request.
    return 2.0 * std::min(settings_.timeout_ms, 20) / 1000.0;
}

DriverStatus ModbusPtu::configure() {
    if (configured_) return DriverStatus::failure("modbus: already configured");
    std::string error;
    std::size_t failed_axis = 0;
    if (!connect_and_set_up(error) || !cycle(error, failed_axis)) {
        link_.close();
        return DriverStatus::failure(error.c_str());
    }
    publish(nullptr);
    configured_ = true;
    running_ = true;
    thread_ = std::thread([this] { run(); });
    return DriverStatus::success();
}

DriverStatus ModbusPtu::activate() {
    if (!configured_) return DriverStatus::failure("modbus: activate before configure");
    enable_pending_ = true;
    active_ = true;
    wake_.fetch_add(1);
    wake_cv_.notify_one();
    const auto deadline =
        clock_.now() + milliseconds(8 * (settings_.retries + 1) * settings_.timeout_ms + 500);
    while (enable_pending_ && clock_.now() < deadline) std::this_thread::sleep_for(milliseconds(2));
    if (enable_pending_) {
        active_ = false;
        return DriverStatus::failure(("modbus: cannot enable the axes: " + last_error_).c_str());
    }
    return DriverStatus::success();
}

void ModbusPtu::deactivate() {
    if (!configured_) return;
    active_ = false;
    running_ = false;
    wake_.fetch_add(1);
    wake_cv_.notify_one();
    if (thread_.joinable()) thread_.join();
    stop_all_best_effort();
    std::string error;
    if (link_.is_open()) write_enable(false, error);
    link_.close();
    configured_ = false;
    last_read_.status = DriverStatus::failure("modbus: not configured");
}

DriverStatus ModbusPtu::home(TimePoint now) {
    (void)now;
    for (const AxisRegisters& axis : map_.axes)
        if (axis.actual_position < 0) return DriverStatus::failure("modbus: this map reads no position, cannot home");
    return DriverStatus::success();  // the drives report absolute positions
}

DriverStatus ModbusPtu::write(const PtuCommand& command, TimePoint now) {
    (void)now;
    if (!active_) return DriverStatus::failure("modbus: write before activate");
    commands_.try_publish([&](CommandSlot& slot) {
        slot.command = command;
        slot.sequence = ++next_sequence_;
    });
    wake_.fetch_add(1, std::memory_order_release);
    wake_cv_.notify_one();
    states_.try_read([&](const StateSlot& slot) { last_read_ = slot; });
    return last_read_.status;
}

DriverStatus ModbusPtu::read(PtuState& state, TimePoint now) {
    states_.try_read([&](const StateSlot& slot) { last_read_ = slot; });
    state = last_read_.state;
    if (!last_read_.status.ok) return last_read_.status;
    const auto limit = milliseconds(settings_.command_timeout_ms + 8 * (settings_.retries + 1) * settings_.timeout_ms);
    if (now - last_read_.state.stamp > limit) return DriverStatus::failure("modbus: no state from the I/O thread");
    return DriverStatus::success();
}

// --- I/O thread ---

void ModbusPtu::run() {
    auto backoff = kMinBackoff;
    TimePoint retry_at = clock_.now();
    while (running_) {
        std::string error;
        if (!link_.is_open()) {
            if (clock_.now() < retry_at) {
                wait_for_wake(std::min(milliseconds(settings_.poll_ms), kMinBackoff));
                continue;
            }
            if (!connect_and_set_up(error)) {
                last_error_ = error;
                publish(error.c_str());
                link_.close();
                retry_at = clock_.now() + backoff;
                backoff = std::min(backoff * 2, kMaxBackoff);
                continue;
            }
        }
        std::size_t failed_axis = 0;
        if (cycle(error, failed_axis)) {
            consecutive_failures_ = 0;
            backoff = kMinBackoff;
        } else if (++consecutive_failures_ >= settings_.fault_after_failures) {
            last_error_ = error;
            io_[failed_axis].link_fault = true;
            publish(error.c_str());
            stop_all_best_effort();  // the other axis at least, if its slave still answers
            link_.close();
            consecutive_failures_ = 0;
            retry_at = clock_.now() + backoff;
            backoff = std::min(backoff * 2, kMaxBackoff);
            continue;
        }
        wait_for_wake(milliseconds(settings_.poll_ms));
    }
}

void ModbusPtu::wait_for_wake(milliseconds period) {
    const std::uint64_t seen = wake_.load(std::memory_order_acquire);
    std::unique_lock lock(wake_mutex_);
    wake_cv_.wait_for(lock, period, [&] { return wake_.load(std::memory_order_acquire) != seen || !running_; });
}

bool ModbusPtu::connect_and_set_up(std::string& error) {
    if (!link_.open(error)) return false;
    for (AxisIo& io : io_) io.target_known = false;
    // Drive-side communication watchdog, once per slave.
    if (map_.watchdog_register >= 0 && settings_.comm_watchdog_ms > 0) {
        const auto counts = static_cast<std::uint16_t>(
            std::clamp(std::lround(settings_.comm_watchdog_ms / map_.watchdog_ms_per_count), 1L, 65535L));
        for (std::size_t i = 0; i < kAxes; ++i) {
            if (i == 1 && map_.axes[1].slave == map_.axes[0].slave) break;
            if (!link_.write(map_.axes[i].slave, map_.watchdog_register, 1, &counts, error)) return false;
        }
    }
    for (const AxisRegisters& axis : map_.axes)
        if (axis.mode >= 0 && !link_.write(axis.slave, axis.mode, 1, &axis.mode_value, error)) return false;
    if (active_) enable_pending_ = true;  // after a reconnect the drive may have dropped its enable
    return true;
}

bool ModbusPtu::write_enable(bool enable, std::string& error) {
    for (const AxisRegisters& axis : map_.axes) {
        if (axis.enable < 0) continue;
        const std::uint16_t value = enable ? axis.enable_value : axis.disable_value;
        if (!link_.write(axis.slave, axis.enable, 1, &value, error)) return false;
    }
    return true;
}

bool ModbusPtu::cycle(std::string& error, std::size_t& failed_axis) {
    const TimePoint now = clock_.now();
    PtuCommand command = PtuCommand::stop();
    commands_.read([&](const CommandSlot& slot) {
        if (slot.sequence != seen_sequence_) {
            seen_sequence_ = slot.sequence;
            last_command_at_ = now;
        }
        command = slot.command;
    });
    const bool stale = seen_sequence_ == 0 || now - last_command_at_ > milliseconds(settings_.command_timeout_ms);
    bool any_fault = false;
    for (const AxisIo& io : io_) any_fault = any_fault || io.drive_fault || io.link_fault;
    if (stale || any_fault || !active_) command = PtuCommand::stop();

    if (enable_pending_ && active_) {
        if (!write_enable(true, error)) return false;
        enable_pending_ = false;
    }
    bool ok = true;
    std::string first_error;
    for (std::size_t i = 0; i < kAxes; ++i) {
        std::string axis_error;
        if (!write_target(i, command.axes[i], now, axis_error) || !read_axis(i, clock_.now(), axis_error)) {
            if (ok) {
                first_error = std::string(kAxisNames[i]) + ": " + axis_error;
                failed_axis = i;
            }
            ok = false;
        }
    }
    if (!ok) {
        error = first_error;
        return false;
    }
    for (AxisIo& io : io_) io.link_fault = false;
    publish(nullptr);
    return true;
}

bool ModbusPtu::write_target(std::size_t i, const AxisCommand& command, TimePoint now, std::string& error) {
    AxisIo& io = io_[i];
    const AxisRegisters& axis = map_.axes[i];
    if (io.target_known && same(io.written, command) && now - io.written_at < kRefresh) return true;
    AxisCommand target = command;
    if (target.mode == CommandMode::Position && axis.position < 0) target = AxisCommand{};  // no position target: stop
    if (target.mode == CommandMode::Velocity && axis.velocity < 0) return true;  // position-only map: hold
    std::uint16_t registers[2] = {0, 0};
    int address = 0, bits = 16;
    if (target.mode == CommandMode::Velocity) {
        address = axis.velocity;
        bits = axis.velocity_bits;
        encode_counts(to_counts(target.value, axis.velocity_counts_per_rad_s, bits), bits, axis.low_word_first, registers);
    } else {
        address = axis.position;
        bits = axis.position_bits;
        encode_counts(to_counts(target.value, axis.position_counts_per_rad, bits), bits, axis.low_word_first, registers);
    }
    io.target_known = false;
    if (!link_.write(axis.slave, address, register_count(bits), registers, error)) return false;
    if (axis.trigger >= 0 && !link_.write(axis.slave, axis.trigger, 1, &axis.trigger_value, error)) return false;
    io.target_known = true;
    io.written = command;
    io.written_at = now;
    return true;
}

bool ModbusPtu::read_axis(std::size_t i, TimePoint now, std::string& error) {
    AxisIo& io = io_[i];
    const AxisRegisters& axis = map_.axes[i];
    if (axis.actual_position >= 0) {
        std::uint16_t registers[2] = {0, 0};
        if (!link_.read(axis.slave, axis.actual_position, register_count(axis.position_bits), registers, error))
            return false;
        const double position =
            decode_counts(registers, axis.position_bits, axis.low_word_first) / axis.position_counts_per_rad;
        const double dt = std::chrono::duration<double>(now - io.position_at).count();
        io.velocity_rad_s = io.have_position && dt > 1e-4 ? (position - io.position_rad) / dt : 0.0;
        io.position_rad = position;
        io.position_at = now;
        io.have_position = true;
    } else {
        io.velocity_rad_s = io.written.mode == CommandMode::Velocity ? io.written.value : 0.0;
    }
    if (axis.status >= 0) {
        std::uint16_t status = 0;
        if (!link_.read(axis.slave, axis.status, 1, &status, error)) return false;
        const bool was_faulted = io.drive_fault;
        io.drive_fault = (status & axis.fault_mask) != 0;
        if (was_faulted && !io.drive_fault && active_) enable_pending_ = true;  // re-enable after the fault clears
    }
    return true;
}

void ModbusPtu::stop_all_best_effort() {
    if (!link_.is_open()) return;
    const TimePoint now = clock_.now();
    for (std::size_t i = 0; i < kAxes; ++i) {
        std::string ignored;
        io_[i].target_known = false;
        write_target(i, AxisCommand{}, now, ignored);
    }
}

void ModbusPtu::publish(const char* failure) {
    char message[120] = {};
    for (std::size_t i = 0; i < kAxes && failure == nullptr; ++i)
        if (io_[i].drive_fault) {
            std::snprintf(message, sizeof message, "modbus: %s: drive reports a fault (status register 0x%04X)",
                          kAxisNames[i], map_.axes[i].status);
            failure = message;
        }
    const TimePoint now = clock_.now();
    states_.publish([&](StateSlot& slot) {
        for (std::size_t i = 0; i < kAxes; ++i) {
            AxisState& axis = slot.state.axes[i];
            axis.position_rad = io_[i].position_rad;
            axis.velocity_rad_s = io_[i].velocity_rad_s;
            axis.fault = io_[i].drive_fault || io_[i].link_fault;
            axis.enabled = active_ && !axis.fault && !enable_pending_;
            axis.homed = map_.axes[i].actual_position >= 0;
        }
        slot.state.stamp = now;
        slot.status = failure == nullptr ? DriverStatus::success() : DriverStatus::failure(failure);
    });
}

std::unique_ptr<PtuDriver> make_modbus_driver(const ModbusSettings& settings, const Clock& clock, std::string& error) {
    if (settings.transport != "tcp" && settings.transport != "rtu") {
        error = "modbus.transport must be tcp or rtu";
        return nullptr;
    }
    if (settings.transport == "rtu" && settings.device.empty()) {
        error = "modbus.device: rtu needs a serial device";
        return nullptr;
    }
    if (settings.transport == "tcp" && settings.host.empty()) {
        error = "modbus.host: tcp needs a host";
        return nullptr;
    }
    auto map = build_register_map(settings, error);
    if (!map) return nullptr;
    return std::make_unique<ModbusPtu>(settings, *map, clock);
}

}  // namespace rays::ptu
