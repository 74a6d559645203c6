// SPDX-License-Identifier: Apache-2.0
#include "daemon/service_notifier.hpp"

#include <systemd/sd-daemon.h>

#include <cstdint>

namespace rays::daemon {

ServiceNotifier::ServiceNotifier() {
    std::uint64_t usec = 0;
    if (sd_watchdog_enabled(0, &usec) > 0) interval_ = std::chrono::microseconds(usec);
}

void ServiceNotifier::ready(const char* status) { sd_notifyf(0, "READY=1\nSTATUS=%s", status); }

void ServiceNotifier::status(const char* status) { sd_notifyf(0, "STATUS=%s", status); }

void ServiceNotifier::stopping() { sd_notify(0, "STOPPING=1"); }

void ServiceNotifier::feed_watchdog(TimePoint now) {
    if (!watchdog_enabled() || now - last_feed_ < interval_ / 2) return;
    last_feed_ = now;
    sd_notify(0, "WATCHDOG=1");
}

}  // namespace rays::daemon
