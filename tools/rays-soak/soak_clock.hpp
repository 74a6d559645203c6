// SPDX-License-Identifier: Apache-2.0
// rays-soak's clock: simulated time between frames, real time within one. set() jumps to a frame's
// capture time; from there now() runs on with the steady clock, so the tracker's deadline is a real
// per-frame budget while the run as a whole goes faster than real time. Never runs backwards.
// In lockstep, time stands still within a frame: no budget is ever reached, every latency reads 0,
// and a run depends on nothing but its settings (the same on every machine, every time).
#pragma once
#include <algorithm>

#include "core/clock.hpp"

namespace rays::soak {

class SoakClock final : public Clock {
public:
    explicit SoakClock(bool lockstep = false) : lockstep_(lockstep) {}

    void set(TimePoint simulated) {
        base_ = std::max(simulated, now());
        mark_ = MonoClock::now();
    }
    TimePoint now() const override { return lockstep_ ? base_ : base_ + (MonoClock::now() - mark_); }

private:
    bool lockstep_;
    TimePoint base_{};
    TimePoint mark_ = MonoClock::now();
};

}  // namespace rays::soak
