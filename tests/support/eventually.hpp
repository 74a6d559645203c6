// SPDX-License-Identifier: Apache-2.0
// Waits in real time for what another thread or process is to do: polls until it is done, for at
// most a generous bound. The bound is there for a loaded machine, not to measure how soon it happens;
// a test never relies on a fixed sleep being long enough.
#pragma once
#include <chrono>
#include <thread>

namespace rays::test {

inline constexpr std::chrono::seconds kEventTimeout{20};

// Polls `done` until it holds; false once kEventTimeout has passed without.
template <class Predicate>
bool eventually(Predicate done) {
    const auto give_up = std::chrono::steady_clock::now() + kEventTimeout;
    while (!done()) {
        if (std::chrono::steady_clock::now() >= give_up) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return true;
}

}  // namespace rays::test
