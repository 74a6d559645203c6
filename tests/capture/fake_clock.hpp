// SPDX-License-Identifier: Apache-2.0
// A clock that moves only when told to (the fake device moves it while "waiting").
#pragma once
#include <chrono>

#include "core/clock.hpp"

namespace rays::test {

class FakeClock final : public Clock {
public:
    TimePoint now() const override { return now_; }
    void advance(std::chrono::nanoseconds step) { now_ += step; }

private:
    TimePoint now_{std::chrono::seconds{1000}};
};

}  // namespace rays::test
