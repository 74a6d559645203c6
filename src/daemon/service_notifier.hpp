// SPDX-License-Identifier: Apache-2.0
// The daemon's messages to systemd through libsystemd's sd_notify: READY=1 once the socket is bound
// and camera and PTU are up, STATUS= lines, STOPPING=1, and WATCHDOG=1 from the frame loop itself so
// that a stalled loop is restarted. Without NOTIFY_SOCKET (not run by systemd) every call is a no-op.
#pragma once
#include <atomic>
#include <chrono>

#include "core/clock.hpp"

namespace rays::daemon {

class ServiceNotifier {
public:
    ServiceNotifier();  // reads WATCHDOG_USEC/WATCHDOG_PID once

    void ready(const char* status);
    void status(const char* status);
    void stopping();

    // Frame loop: sends WATCHDOG=1 when half the watchdog interval has passed since the last one.
    // No allocation; one datagram to systemd's notify socket when due (every few seconds), which
    // systemd drains at once, so the send does not wait.
    void feed_watchdog(TimePoint now);

    bool watchdog_enabled() const { return interval_.count() > 0; }
    std::chrono::microseconds watchdog_interval() const { return interval_; }

private:
    std::chrono::microseconds interval_{0};
    TimePoint last_feed_{};
};

}  // namespace rays::daemon
