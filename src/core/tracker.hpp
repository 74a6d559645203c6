// SPDX-License-Identifier: Apache-2.0
// The tracking state machine: detecting → tracking → lost → detecting (§4.1), with the motion
// detector for initialisation, active rays for the contour, the attention module for loss, and a
// constant-velocity prediction of the reference point (the paper's future work).
#pragma once
#include <optional>
#include <vector>

#include "core/active_rays.hpp"
#include "core/attention.hpp"
#include "core/background_model.hpp"
#include "core/clock.hpp"
#include "core/contour_tracker.hpp"
#include "core/gaussian_smoother.hpp"
#include "core/motion_detector.hpp"

namespace rays {

class Tracker final : public ContourTracker {
public:
    // Sizes every buffer from config.capacity; nothing is allocated after this.
    Tracker(const TrackerConfig& config, const Clock& clock);

    // Applies new tunables within the capacities without allocating; false (nothing changed) if invalid.
    const char* method() const override { return "rays"; }
    bool set_tunables(const TrackerTunables& tunables) override;
    const TrackerTunables& tunables() const { return tunables_; }
    const TrackerCapacity& capacity() const { return capacity_; }

    void start_at(Point m) override;
    bool start_in(const Box& box) override;
    void reacquire_at(Point m) override;
    void release() override;
    void reinit() override;
    void predict_next(Point m) override { external_prediction_ = m; }
    void allow_detection(bool allowed) override;

    // Processes one frame; refinement stops before `deadline`. No allocation, no exceptions.
    const FrameResult& process(const GreyImage& frame, TimePoint deadline) override;

    TrackState state() const { return result_.state; }
    const FrameResult& result() const override { return result_; }
    const Contour& contour() const override { return contour_; }
    const ActiveRays& rays() const { return rays_; }

private:
    Point best_start(Point centre, double radius, TimePoint deadline);
    // Starts a track at m; `same_target`: a re-acquisition, keeping the target's learned looks.
    bool begin_track(Point m, double radius, bool search, bool same_target, TimePoint deadline);
    // Starts a track in a box: the box's ellipse the first contour's prior, its inside the target's looks.
    bool begin_box_track(const Box& box, TimePoint deadline);
    // The new track's first contour from m with the prior and looks set up: false if it is no target.
    bool first_contour(Point m, bool same_target, TimePoint deadline);
    bool reacquire_afresh(Point m, double radius, TimePoint deadline);
    void track(TimePoint deadline);
    // A track standing still on something beside the mover: false (see .cpp).
    bool watch_still_track(const GreyImage& frame);
    void remember_contour();
    void declare_lost(const char* reason);  // this frame's contour is not the target: lost, for `reason`

    const Clock& clock_;
    TrackerCapacity capacity_;
    TrackerTunables tunables_;
    GaussianSmoother smoother_;
    FloatImage smoothed_;
    GreyImage previous_;
    bool has_previous_ = false;
    MotionDetector detector_;
    BackgroundModel background_;  // the still camera's background, for the rays' foreground term
    ActiveRays rays_;
    PolarPrior prior_;
    TargetModel model_;
    Attention attention_;
    Contour contour_;
    std::vector<Point> last_points_;  // the previous contour, for the temporal prior
    std::vector<unsigned char> last_open_;  // its points without an edge
    std::vector<float> scratch_;
    int last_count_ = 0;
    Point velocity_;
    std::optional<Point> start_point_;
    std::optional<Box> start_box_;  // a box start: start_point_ is its centre
    bool reacquire_ = false;  // start_point_ is a re-acquisition of the last target
    std::optional<Point> external_prediction_;  // from predict_next(), for the next frame only
    bool detection_allowed_ = true;
    int lost_frames_ = 0;
    int untracked_frames_ = 0;  // frames since the last one with a contour
    int still_frames_ = -1;   // frames the track has stood still near still_at_ (-1: a new track)
    Point still_at_;          // where it stands
    bool watched_ = true;     // detection started the track, or it has moved since its start point
    int motion_inside_ = 0;   // of this window's still frames, those whose motion was found in the contour
    int motion_outside_ = 0;  // ... and away from it
    double tracked_area_ = 0;   // area of the last contour accepted as the target
    WholeArea whole_area_;      // the target's size, for looking for it again after an occlusion
    double whole_grey_ = 0;     // its inside grey / the frame's mean grey while whole (running; 0: none yet)
    FrameResult result_;
};

}  // namespace rays
