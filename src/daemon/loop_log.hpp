// SPDX-License-Identifier: Apache-2.0
// Log lines from the frame loop, which must not block on stderr: formatted into fixed-size entries
// of a lock-free ring and written by the socket thread (drain()). A full ring drops and counts.
#pragma once
#include <array>
#include <atomic>
#include <cstdarg>

#include "daemon/log.hpp"
#include "common/spsc_ring.hpp"

namespace rays::daemon {

class LoopLog {
public:
    // Frame loop only.
    [[gnu::format(printf, 3, 4)]] void log(Priority priority, const char* format, ...);
    // Socket thread only: writes every queued line through log_text().
    void drain();
    long dropped() const { return dropped_.load(std::memory_order_relaxed); }

private:
    struct Line {
        Priority priority = Priority::Info;
        const char* key = nullptr;  // the format string: repeats of one message share it
        std::array<char, 200> text{};
    };
    SpscRing<Line, 64> lines_;
    std::atomic<long> dropped_{0};
};

}  // namespace rays::daemon
