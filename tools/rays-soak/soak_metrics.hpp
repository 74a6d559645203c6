// SPDX-License-Identifier: Apache-2.0
// What a closed-loop run achieved, judged only against the simulator's ground truth, never the
// tracker's own state. A loss is the true target centre leaving the image, or the contour's centre
// more than 10 % of the image size from the true centre (or no contour) for more than 5 frames,
// counted from the first frame on target (before it, the target is being acquired).
#pragma once
#include <array>
#include <vector>

#include "core/image.hpp"

namespace rays::soak {

inline constexpr double kOnTargetPx = 0.1 * kFrameSize;  // 10 % of the image size
inline constexpr int kOffFramesForLoss = 5;              // off target for more than this: lost

struct SoakFrame {
    double t_s = 0;
    bool target_in_image = false;  // the true target centre lies within the frame
    Point truth_px;                // the true target centre, processing pixels
    bool has_contour = false;
    Point contour_px;              // the contour's centre
    double speed_deg_s = 0;        // the target's true angular speed
    double speed_px_frame = 0;     // the same in processing pixels per frame
    float latency_us = 0;          // capture to PTU write
    double pan_deg = 0, tilt_deg = 0;            // the unit
    double pan_rate_deg_s = 0, tilt_rate_deg_s = 0;
    double target_az_deg = 0, target_el_deg = 0;  // the target, world angles, relative to the rig
};

// What the first frame off target showed: where to look for the loss's cause.
enum class LossCause {
    LeftImage,  // the true centre was outside the image (the unit did not keep up)
    NoContour,  // the tracker had no contour (it declared the target lost, or was still looking)
    OffTarget,  // the tracker had a contour, away from the target (it slid onto something else)
};
const char* to_string(LossCause cause);
// Every cause, in the order the totals list them.
inline constexpr std::array<LossCause, 3> kLossCauses = {LossCause::NoContour, LossCause::OffTarget, LossCause::LeftImage};

struct Loss {
    double start_s = 0;     // first frame off target
    double reacquire_s = -1;  // time to be on target again; < 0: never
    LossCause cause = LossCause::OffTarget;
};

struct SoakSummary {
    long frames = 0;
    double acquired_s = -1;        // first frame on target; < 0: never
    std::vector<Loss> losses;
    double centred_fraction = 0;   // frames with the true centre within 10 % of the image size of the centre
    double on_target_fraction = 0; // frames with the contour's centre within 10 % of the true centre
    double max_speed_deg_s = 0;    // fastest true speed while on target, before the first loss
    double max_speed_px_frame = 0;
    double latency_median_us = 0;
    double latency_p99_us = 0;
    double max_abs_pan_rate_deg_s = 0;
    double max_abs_tilt_rate_deg_s = 0;
    double pan_min_deg = 0, pan_max_deg = 0, tilt_min_deg = 0, tilt_max_deg = 0;
};

bool on_target(const SoakFrame& frame);
SoakSummary summarise(const std::vector<SoakFrame>& frames);

}  // namespace rays::soak
