// SPDX-License-Identifier: Apache-2.0
#include "control/pose_history.hpp"

namespace rays::control {

void PoseHistory::record(const UnitPose& pose) {
    if (count_ > 0 && pose.t_s < nth_newest(0).t_s) return;
    if (count_ > 0 && pose.t_s == nth_newest(0).t_s) {
        poses_[(next_ + kCapacity - 1) % kCapacity] = pose;  // the same report again, maybe with news
        return;
    }
    poses_[next_] = pose;
    next_ = (next_ + 1) % kCapacity;
    if (count_ < kCapacity) ++count_;
}

UnitPose PoseHistory::at(double t_s) const {
    if (count_ == 0) return UnitPose{}.at(t_s);
    if (t_s >= nth_newest(0).t_s) return nth_newest(0).at(t_s);
    for (std::size_t k = 1; k < count_; ++k) {
        const UnitPose& before = nth_newest(k);
        if (before.t_s > t_s) continue;
        const UnitPose& after = nth_newest(k - 1);
        const double w = (t_s - before.t_s) / (after.t_s - before.t_s);
        auto mix = [w](double a, double b) { return a + w * (b - a); };
        return {t_s, mix(before.pan, after.pan), mix(before.tilt, after.tilt), mix(before.pan_rate, after.pan_rate),
                mix(before.tilt_rate, after.tilt_rate)};
    }
    return nth_newest(count_ - 1).at(t_s);
}

}  // namespace rays::control
