// SPDX-License-Identifier: Apache-2.0
// What the frame loop and rays-soak need of a contour tracker, so that active rays (Tracker) and the
// greedy-snake baseline (snake/greedy_snake_tracker.hpp) run in the same closed loop.
// Implementations size every buffer in their constructor and never allocate, block or throw in
// process().
#pragma once
#include <optional>
#include "core/box.hpp"
#include "core/clock.hpp"
#include "core/contour.hpp"
#include "core/image.hpp"
#include "core/motion_detector.hpp"
#include "core/tracker_config.hpp"

namespace rays {

enum class TrackState { Detecting, Tracking, Lost };

extern const Chroma kNoChroma;  // a mono frame's colour: none
const char* to_string(TrackState s);

struct FrameResult {
    long frame = -1;
    TrackState state = TrackState::Detecting;
    bool has_contour = false;      // true while tracking
    Point predicted;               // where m was expected this frame
    Detection detection;           // the motion detector's output, on frames it ran
    // Why the track was lost this frame; with the state tracking again, the target was found again
    // in the same frame (attention.lost_frames = 0).
    const char* lost_reason = nullptr;
    // How surely the target's looks were found this frame: the correlation filter's peak-to-sidelobe
    // ratio where it found the target (about 5 and up: sure; 0 where it did not look, as for a new
    // target's first frame and for a tracker without a filter). The filter learns what the track
    // holds: a track on background can be sure of it too.
    double match_psr = 0.0;
    // The track just dropped was not on the target (it stood on background while the target moved
    // on): where it was is no place to look for the target again.
    bool off_target = false;
};

class ContourTracker {
public:
    virtual ~ContourTracker() = default;

    virtual const char* method() const = 0;  // "rays" | "snake"

    // New tunables within the capacities, without allocating; false (nothing changed) if invalid.
    virtual bool set_tunables(const TrackerTunables& tunables) = 0;

    virtual void start_at(Point m) = 0;  // a start point from the user replaces detection on the next frame
    // Like start_at, with the target's extent: a box start gives the tracker the target's extent, a
    // point start finds it. False (nothing changed) when box_problem(box) says why it cannot.
    virtual bool start_in(const Box& box) = 0;
    // Like start_at, for the target just lost (a predictor says where it should be now): what the
    // tracker learned of its looks is kept, so something else at that point is not taken for it.
    virtual void reacquire_at(Point m) = 0;
    virtual void release() = 0;          // drop the target and detect again
    // release, restart the detector's threshold adaptation, and forget that a person chose the target
    // (its size no longer bounds what the detector takes)
    virtual void reinit() = 0;

    // Where the target's reference point will be in the next frame, from a predictor that knows more
    // than the image (the camera's own motion, a Kalman filter on the target): used once, by the next
    // process(), instead of the tracker's own constant-velocity guess.
    virtual void predict_next(Point m) = 0;
    // Frame differencing only makes sense while the camera holds still: while false, a detecting
    // tracker does not run the motion detector. The caller allows it only when the camera stood
    // still from the previous frame's capture to this one's.
    virtual void allow_detection(bool allowed) = 0;
    // How far the unit's own turning moved the view from the previous frame's capture to this one's
    // (px, this(x) = previous(x − shift)), from the unit's reported angles; none where the caller
    // does not know (a recording). Used by the next process() only.
    virtual void expect_view_shift(std::optional<Point> shift) = 0;

    // Processes one frame, with its colour where the source has some (chroma.present); refinement
    // stops before `deadline`.
    virtual const FrameResult& process(const GreyImage& frame, const Chroma& chroma, TimePoint deadline) = 0;
    // A frame without colour.
    const FrameResult& process(const GreyImage& frame, TimePoint deadline) { return process(frame, kNoChroma, deadline); }

    virtual const FrameResult& result() const = 0;
    virtual const Contour& contour() const = 0;  // valid while result().has_contour
};

}  // namespace rays
