// SPDX-License-Identifier: Apache-2.0
// A fixed-size lock-free queue between exactly one producer thread and one consumer thread. It never
// overwrites: push() on a full ring fails and the producer counts the loss. Used for commands into
// the frame loop and for telemetry and log lines out of it.
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <type_traits>

namespace rays {

template <class T, std::size_t N>
class SpscRing {
    static_assert(std::is_trivially_copyable_v<T>, "ring entries are copied without allocation");
    static_assert(N >= 2 && (N & (N - 1)) == 0, "capacity is a power of two");

public:
    bool push(const T& item) {
        std::size_t head = head_.load(std::memory_order_relaxed);
        if (head - tail_.load(std::memory_order_acquire) == N) return false;
        slots_[head % N] = item;
        head_.store(head + 1, std::memory_order_release);
        return true;
    }

    bool pop(T& item) {
        std::size_t tail = tail_.load(std::memory_order_relaxed);
        if (tail == head_.load(std::memory_order_acquire)) return false;
        item = slots_[tail % N];
        tail_.store(tail + 1, std::memory_order_release);
        return true;
    }

    bool empty() const { return tail_.load(std::memory_order_acquire) == head_.load(std::memory_order_acquire); }

private:
    std::array<T, N> slots_{};
    alignas(64) std::atomic<std::size_t> head_{0};
    alignas(64) std::atomic<std::size_t> tail_{0};
};

}  // namespace rays
