// SPDX-License-Identifier: Apache-2.0
// Time enters the core only through this interface, so tests can drive deadlines.
#pragma once
#include <chrono>

namespace rays {

using MonoClock = std::chrono::steady_clock;
using TimePoint = MonoClock::time_point;

class Clock {
public:
    virtual ~Clock() = default;
    virtual TimePoint now() const = 0;
};

class SteadyClock final : public Clock {
public:
    TimePoint now() const override { return MonoClock::now(); }
};

}  // namespace rays
