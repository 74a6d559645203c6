// SPDX-License-Identifier: Apache-2.0
#include "sim/exposure_delay.hpp"

#include <algorithm>

namespace rays::sim {

ExposureDelay::ExposureDelay(int latency_frames, double fps, bool stamp_exposure)
    : latency_(std::clamp(latency_frames, 0, kMaxFrames)), fps_(fps), stamp_exposure_(stamp_exposure) {}

ExposureDelay::Exposure ExposureDelay::deliver(long k, const control::UnitPose& unit) {
    constexpr long kSlots = kMaxFrames + 1;
    poses_[static_cast<std::size_t>(k % kSlots)] = unit;
    const long index = shown(k);
    return {index, static_cast<double>(index) / fps_, poses_[static_cast<std::size_t>(index % kSlots)]};
}

TimePoint::duration ExposureDelay::stamp_lead(long k) const {
    if (!stamp_exposure_) return TimePoint::duration::zero();
    return std::chrono::duration_cast<TimePoint::duration>(
        std::chrono::duration<double>(static_cast<double>(k - shown(k)) / fps_));
}

}  // namespace rays::sim
