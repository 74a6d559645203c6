// SPDX-License-Identifier: Apache-2.0
// The unit's recent poses as it reported them, so a frame exposed a while before it reached the loop
// (camera latency) is paired with where the camera really pointed at its exposure, not with a pose
// extrapolated back from now. A fixed ring: recording and looking up never allocate.
#pragma once
#include <array>
#include <cstddef>

#include "control/controller.hpp"

namespace rays::control {

class PoseHistory {
public:
    static constexpr std::size_t kCapacity = 64;  // at the loop's ≥ 20 writes/s, more than 3 s back

    // A pose the unit reported; times must not decrease (an older one is ignored).
    void record(const UnitPose& pose);
    // The pose at `t_s`: linear between the two reports round it, extrapolated at the reported rate
    // beyond the newest or before the oldest. A default pose while nothing was recorded.
    UnitPose at(double t_s) const;

private:
    const UnitPose& nth_newest(std::size_t k) const { return poses_[(next_ + kCapacity - 1 - k) % kCapacity]; }

    std::array<UnitPose, kCapacity> poses_{};
    std::size_t next_ = 0, count_ = 0;
};

}  // namespace rays::control
