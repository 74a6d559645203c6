// SPDX-License-Identifier: Apache-2.0
#include "daemon/log.hpp"

#include <array>
#include <cstdio>
#include <mutex>

namespace rays::daemon {
namespace {

using Clock = std::chrono::steady_clock;

struct RepeatSlot {
    const void* key = nullptr;
    Clock::time_point last_written{};
    long held_back = 0;
};

struct LogState {
    std::mutex mutex;
    Priority level = Priority::Info;
    Clock::duration repeat_interval = std::chrono::seconds(10);
    std::array<RepeatSlot, 64> slots{};  // the most recent distinct messages; the oldest slot is reused
    std::size_t next_slot = 0;
};

LogState& state() {
    static LogState instance;
    return instance;
}

// The slot for `key`, or a recycled one. Caller holds the mutex.
RepeatSlot& slot_for(LogState& s, const void* key) {
    for (RepeatSlot& slot : s.slots)
        if (slot.key == key) return slot;
    RepeatSlot& slot = s.slots[s.next_slot];
    s.next_slot = (s.next_slot + 1) % s.slots.size();
    slot = RepeatSlot{key, {}, 0};
    return slot;
}

}  // namespace

bool parse_priority(std::string_view name, Priority& out) {
    constexpr std::array<std::pair<std::string_view, Priority>, 5> names = {{{"err", Priority::Err},
                                                                             {"warning", Priority::Warning},
                                                                             {"notice", Priority::Notice},
                                                                             {"info", Priority::Info},
                                                                             {"debug", Priority::Debug}}};
    for (const auto& [word, priority] : names) {
        if (word != name) continue;
        out = priority;
        return true;
    }
    return false;
}

void set_log_level(Priority least_important) {
    std::lock_guard lock(state().mutex);
    state().level = least_important;
}

void set_log_repeat_interval(std::chrono::duration<double> interval) {
    std::lock_guard lock(state().mutex);
    state().repeat_interval = std::chrono::duration_cast<Clock::duration>(interval);
}

void log_text(Priority priority, const void* key, std::string_view text) {
    LogState& s = state();
    std::lock_guard lock(s.mutex);
    if (static_cast<int>(priority) > static_cast<int>(s.level)) return;
    Clock::time_point now = Clock::now();
    RepeatSlot& slot = slot_for(s, key);
    if (slot.last_written != Clock::time_point{} && now - slot.last_written < s.repeat_interval) {
        ++slot.held_back;
        return;
    }
    if (slot.held_back > 0)
        std::fprintf(stderr, "<%d>%.*s (repeated %ld more times)\n", static_cast<int>(priority),
                     static_cast<int>(text.size()), text.data(), slot.held_back);
    else
        std::fprintf(stderr, "<%d>%.*s\n", static_cast<int>(priority), static_cast<int>(text.size()), text.data());
    std::fflush(stderr);
    slot.last_written = now;
    slot.held_back = 0;
}

void vlog(Priority priority, const char* format, std::va_list args) {
    std::array<char, 512> text{};
    int length = std::vsnprintf(text.data(), text.size(), format, args);
    if (length < 0) return;
    std::size_t size = std::min(static_cast<std::size_t>(length), text.size() - 1);
    log_text(priority, format, std::string_view(text.data(), size));
}

void log(Priority priority, const char* format, ...) {
    std::va_list args;
    va_start(args, format);
    vlog(priority, format, args);
    va_end(args);
}

}  // namespace rays::daemon
