// SPDX-License-Identifier: Apache-2.0
// The part every CAN drive driver shares: the transport, its own I/O thread, and the fixed mailboxes
// between that thread and the frame loop (LatestValue: write/read never wait, block or allocate).
// A protocol (CANopen, ODrive) implements the io_* hooks, which run on the I/O thread only.
//
// The I/O thread wakes on every received frame, on write() (transport wake()) and every cycle_s.
// It gives the protocol the newest command, or a stop when no write() came for command_timeout_s
// (stale) or the axes are not to be enabled. A failing interface is closed and reopened with
// backoff (0.5 s doubling to 8 s), the protocol starting afresh each time.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>

#include "common/latest_value.hpp"
#include "core/clock.hpp"
#include "drivers/can/can_transport.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::can {

struct CanIoTiming {
    double cycle_s = 0.01;
    double command_timeout_s = 0.5;
    double lifecycle_timeout_s = 3.0;  // configure() and activate() wait at most this
};

enum class Goal { Configured, Enabled, Off };

// What the I/O thread last saw, for read() and write().
struct IoReport {
    ptu::PtuState state;
    ptu::DriverStatus status;
    bool configured = false;  // every axis answered and took its configuration
    bool enabled = false;     // every axis is enabled and fault-free
    ptu::DriverStatus waiting;  // what configure/activate still wait for, as their timeout message
};

class CanIoDriver : public ptu::PtuDriver {
public:
    ptu::DriverStatus configure() override;
    ptu::DriverStatus activate() override;
    void deactivate() override;
    ptu::DriverStatus write(const ptu::PtuCommand& command, TimePoint now) override;
    ptu::DriverStatus read(ptu::PtuState& state, TimePoint now) override;

protected:
    CanIoDriver(std::unique_ptr<CanTransport> transport, const Clock& clock, const CanIoTiming& timing);
    // Derived destructors call this first: the thread must end before the hooks' object goes.
    void stop_thread();

    // I/O thread hooks.
    virtual void io_start(TimePoint now) = 0;  // (re)connected: begin the bring-up from scratch
    virtual void io_frame(const can_frame& frame, TimePoint now) = 0;
    virtual void io_bus_event(CanBusEvent event, TimePoint now) = 0;
    // Each wake-up: `command` is the newest (a stop when stale or not enabled); `fresh` when it
    // arrived since the last call.
    virtual void io_cycle(const ptu::PtuCommand& command, bool fresh, TimePoint now) = 0;
    virtual void io_stop(TimePoint now) = 0;  // deactivate: stop and disable the axes
    virtual IoReport io_report(TimePoint now) = 0;

    Goal goal() const { return goal_.load(); }
    bool send(const can_frame& frame);  // I/O thread; false when dropped or the link is down
    const char* prefix_name() const { return name(); }

private:
    struct CommandMail {
        ptu::PtuCommand command;
        std::uint64_t sequence = 0;
    };

    void run();
    void publish(TimePoint now);
    bool wait_for(bool IoReport::*flag, ptu::DriverStatus& failure);
    bool reopen(TimePoint now);

    std::unique_ptr<CanTransport> transport_;
    const Clock& clock_;
    const CanIoTiming timing_;
    std::atomic<Goal> goal_{Goal::Off};
    std::atomic<bool> running_{false};
    std::thread thread_;
    LatestValue<CommandMail> command_;
    LatestValue<IoReport> report_;
    // Frame-loop side.
    std::uint64_t written_ = 0;
    ptu::DriverStatus last_status_;
    // I/O side.
    bool link_down_ = false;
    ptu::DriverStatus link_status_;
    TimePoint next_open_{};
    double open_backoff_s_ = 0.5;
};

}  // namespace rays::can
