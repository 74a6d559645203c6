// SPDX-License-Identifier: Apache-2.0
// A clock the test moves by hand, and seconds as TimePoints on it.
#pragma once
#include <chrono>

#include "core/clock.hpp"

namespace rays::test {

inline TimePoint at_seconds(double seconds) {
    return TimePoint{} + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(seconds));
}

class ManualClock final : public Clock {
public:
    TimePoint now() const override { return now_; }
    void set_seconds(double seconds) { now_ = at_seconds(seconds); }

private:
    TimePoint now_{};
};

}  // namespace rays::test
