// SPDX-License-Identifier: Apache-2.0
// PtuDriver over Modbus (TCP or RTU). libmodbus is synchronous, so every bus call runs on the
// driver's own I/O thread; write() and read() only exchange the newest command and the newest
// state with it through LatestValue mailboxes (no blocking, no allocation).
//
// The I/O thread, each cycle (poll_ms, or at once when write() brings a command): takes the newest
// command — or zero velocity when none came for command_timeout_ms, while not active, or while an
// axis is faulted — writes the targets that changed, reads actual position and status, and
// publishes the state. A request fails after timeout_ms × (retries + 1) or on an exception reply;
// after fault_after_failures consecutive failed cycles the axis that failed is faulted, the other
// stopped, the link closed and reopened with backoff (0.1 s doubling to 2 s); once a cycle succeeds
// again read() is ok. A status fault bit faults its axis and stops the other until it clears.
// On connecting it writes comm_watchdog_ms to the drive's watchdog register where the map has one.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "common/latest_value.hpp"
#include "core/clock.hpp"
#include "drivers/modbus/modbus_link.hpp"
#include "drivers/modbus/modbus_settings.hpp"
#include "drivers/modbus/register_map.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

class ModbusPtu final : public PtuDriver {
public:
    ModbusPtu(const ModbusSettings& settings, const RegisterMap& map, const Clock& clock);
    ~ModbusPtu() override;

    const char* name() const override { return "modbus"; }
    double command_latency_s() const override;
    DriverStatus configure() override;
    DriverStatus activate() override;
    void deactivate() override;
    DriverStatus home(TimePoint now) override;
    DriverStatus write(const PtuCommand& command, TimePoint now) override;
    DriverStatus read(PtuState& state, TimePoint now) override;

private:
    struct CommandSlot {
        PtuCommand command;
        std::uint64_t sequence = 0;
    };
    struct StateSlot {
        PtuState state;
        DriverStatus status;
    };
    struct AxisIo {  // I/O thread only
        bool target_known = false;  // the last target written reached the drive
        AxisCommand written{};
        TimePoint written_at{};
        bool have_position = false;
        double position_rad = 0.0;
        TimePoint position_at{};
        double velocity_rad_s = 0.0;
        bool drive_fault = false;
        bool link_fault = false;
    };

    void run();
    bool connect_and_set_up(std::string& error);
    bool write_enable(bool enable, std::string& error);
    bool cycle(std::string& error, std::size_t& failed_axis);
    bool write_target(std::size_t axis, const AxisCommand& command, TimePoint now, std::string& error);
    bool read_axis(std::size_t axis, TimePoint now, std::string& error);
    void stop_all_best_effort();
    void publish(const char* failure);
    void wait_for_wake(std::chrono::milliseconds period);

    const ModbusSettings settings_;
    const RegisterMap map_;
    const Clock& clock_;
    ModbusLink link_;
    std::thread thread_;
    std::atomic<bool> running_{false};
    std::atomic<bool> active_{false};
    std::atomic<bool> enable_pending_{false};
    bool configured_ = false;

    LatestValue<CommandSlot> commands_;
    LatestValue<StateSlot> states_;
    std::uint64_t next_sequence_ = 0;  // frame thread
    StateSlot last_read_{};            // frame thread: what read() answers when the mailbox is busy
    std::atomic<std::uint64_t> wake_{0};
    std::mutex wake_mutex_;
    std::condition_variable wake_cv_;

    // I/O thread
    std::array<AxisIo, kAxes> io_{};
    std::uint64_t seen_sequence_ = 0;
    TimePoint last_command_at_{};
    int consecutive_failures_ = 0;
    std::string last_error_;
};

// Checks the settings (preset, map, transport) and builds the driver; null with `error` otherwise.
std::unique_ptr<PtuDriver> make_modbus_driver(const ModbusSettings& settings, const Clock& clock, std::string& error);

}  // namespace rays::ptu
