// SPDX-License-Identifier: Apache-2.0
#include "daemon/loop_log.hpp"

#include <cstdio>
#include <string_view>

namespace rays::daemon {

void LoopLog::log(Priority priority, const char* format, ...) {
    Line line;
    line.priority = priority;
    line.key = format;
    std::va_list args;
    va_start(args, format);
    std::vsnprintf(line.text.data(), line.text.size(), format, args);
    va_end(args);
    if (!lines_.push(line)) dropped_.fetch_add(1, std::memory_order_relaxed);
}

void LoopLog::drain() {
    Line line;
    while (lines_.pop(line)) log_text(line.priority, line.key, std::string_view(line.text.data()));
}

}  // namespace rays::daemon
