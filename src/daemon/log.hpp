// SPDX-License-Identifier: Apache-2.0
// Logging to stderr with sd-daemon priority prefixes ("<4>camera lost"), which journald turns into
// priorities. A message repeated within the repeat interval is written once; the next time it is
// written it says how many repeats were held back. Safe from any thread except the frame loop,
// which must not block on stderr: it queues fixed-size lines with LoopLog (loop_log.hpp) instead.
#pragma once
#include <chrono>
#include <cstdarg>
#include <string_view>

namespace rays::daemon {

enum class Priority { Err = 3, Warning = 4, Notice = 5, Info = 6, Debug = 7 };

// "err", "warning", "notice", "info", "debug"; false for anything else.
bool parse_priority(std::string_view name, Priority& out);

void set_log_level(Priority least_important);
void set_log_repeat_interval(std::chrono::duration<double> interval);

// printf-style. Messages with the same format string count as repeats of one another.
[[gnu::format(printf, 2, 3)]] void log(Priority priority, const char* format, ...);
void vlog(Priority priority, const char* format, std::va_list args);

// Writes one already formatted message, repeat-limited by `key`.
void log_text(Priority priority, const void* key, std::string_view text);

}  // namespace rays::daemon
