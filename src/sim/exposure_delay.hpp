// SPDX-License-Identifier: Apache-2.0
// A camera that delivers each frame `latency_frames` frame periods after its exposure (sim.latency_frames):
// which exposure the k-th delivered frame shows, the unit's pose at that moment, and how long before
// its delivery the frame is stamped — the latency for a camera that stamps its exposures (as V4L2
// does), 0 for one that does not. Used by raysd's simulated source, rays-soak and the loop tests.
// A fixed ring of poses: no allocation.
#pragma once
#include <array>

#include "control/controller.hpp"
#include "core/clock.hpp"

namespace rays::sim {

class ExposureDelay {
public:
    static constexpr int kMaxFrames = 15;  // sim.latency_frames at most

    ExposureDelay(int latency_frames, double fps, bool stamp_exposure);

    struct Exposure {
        long index;               // the frame exposed then: max(0, k - latency_frames)
        double t_s;               // its exposure time, seconds from the first frame
        control::UnitPose unit;   // the unit's pose given for that frame's delivery
    };
    // Frames are delivered in order k = 0, 1, …; `unit` is the unit's pose at delivery k.
    Exposure deliver(long k, const control::UnitPose& unit);
    // How long before its delivery frame k is stamped.
    TimePoint::duration stamp_lead(long k) const;

private:
    long shown(long k) const { return k > latency_ ? k - latency_ : 0; }

    int latency_;
    double fps_;
    bool stamp_exposure_;
    std::array<control::UnitPose, kMaxFrames + 1> poses_{};
};

}  // namespace rays::sim
