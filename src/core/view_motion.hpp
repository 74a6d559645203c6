// SPDX-License-Identifier: Apache-2.0
// How the view itself moved between two frames: the camera turned (a pan/tilt unit the daemon does
// not command, a hand-held or vehicle camera, a recording), not just something in it. Frame
// differencing (§4.1) needs the two frames aligned, a learned background a still view. The estimate
// comes from the frames' integral projections (the column and row sums, as in projection-based video
// stabilisation), per band of the frame: a moving view shifts every band's projection alike, movers
// only the bands they fill, each by its own amount. So the view is still where a good share of the
// bands did not move or cannot tell (a crowd walking across the lower half of a still view leaves
// the upper half still; a plain background round a lone mover shows nothing else moving), and
// otherwise moved by the shift a good share of the bands agree on. A runner the camera follows,
// still in the image, fills too little of any band to hold the view still. Fixed memory, a few
// microseconds a frame.
#pragma once
#include <array>
#include <optional>

#include "core/image.hpp"

namespace rays {

// The previous frame aligned with this one, `frame`, by the view's `shift` (ViewShift::shift or
// drift), so that differencing the two shows what moved in the scene: `previous` itself for no shift,
// else `out`, where this frame at x is the previous one at x − shift and this frame's own pixel stands
// in where that is off the previous frame (no difference there).
const GreyImage& align_previous(const GreyImage& previous, const GreyImage& frame, Point shift, GreyImage& out);

struct ViewShift {
    bool known = false;  // compared with a previous frame, and enough bands agreed
    bool still = false;  // known, and the view did not move
    Point shift;         // px from the previous frame to this one: this(x) = previous(x − shift)
    // px the view moved, as well as the bands measure it: `shift` when it moved; when still, what the
    // bands that did not move still moved by (a slow pan moves less than kAgreePx a frame, and
    // that adds up over frames).
    Point drift;
};

class ViewMotion {
public:
    static constexpr int kBands = 8;              // bands across each axis, each with its own projection
    static constexpr int kMaxShiftPx = 6;         // shifts searched either way on each axis
    // A band that moved less is still (differencing an edge moved this far leaves a quarter of its
    // contrast); bands whose shifts differ by less agree ...
    static constexpr double kAgreePx = 0.25;
    static constexpr int kShare = 3;  // ... and the view goes with 1 / this of the bands, at least


    // Takes the next frame's projections (every frame, so that the previous one's are at hand).
    void take(const FloatImage& smoothed);
    // How the view moved from the previous frame to the one taken last (unknown for the first frame
    // after a reset); worked out on the first call after take(). Flat bands (a clear sky) and bands
    // that match at no shift (noise) tell nothing, which counts for a still view.
    const ViewShift& since_previous();

private:
    using Profile = std::array<float, kFrameSize>;
    struct Projections {
        std::array<Profile, kBands> profile{};
        std::array<bool, kBands> tells{};  // not too flat to tell a shift
    };
    // The shift, sub-pixel, that best aligns `now` with `before` (both normalised); none when even
    // that one does not match.
    static std::optional<double> best_shift(const Profile& before, const Profile& now);
    // The view's shift along one axis from the bands' shifts, and its drift (ViewShift::drift):
    // false when too few bands agree.
    bool agreed_shift(const Projections& before, const Projections& now, double& shift, double& drift);

    Projections columns_, rows_, previous_columns_, previous_rows_;  // x shifts from columns, y from rows
    std::array<double, kBands> shifts_{};
    ViewShift view_;
    bool has_previous_ = false, compared_ = false, measured_ = false;
};

}  // namespace rays
