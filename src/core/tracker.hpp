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
#include "core/box_start.hpp"
#include "core/chosen_target.hpp"
#include "core/clock.hpp"
#include "core/contour_tracker.hpp"
#include "core/correlation_filter.hpp"
#include "core/frame_sweep.hpp"
#include "core/gaussian_smoother.hpp"
#include "core/motion_detector.hpp"
#include "core/still_track_watch.hpp"
#include "core/target_likelihood.hpp"
#include "core/view_motion.hpp"

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
    void expect_view_shift(std::optional<Point> shift) override { expected_view_ = shift; }

    // Processes one frame; refinement stops before `deadline`. No allocation, no exceptions.
    using ContourTracker::process;
    const FrameResult& process(const GreyImage& frame, const Chroma& chroma, TimePoint deadline) override;

    TrackState state() const { return result_.state; }
    const FrameResult& result() const override { return result_; }
    const Contour& contour() const override { return contour_; }
    const ActiveRays& rays() const { return rays_; }
    const AppearanceModel& appearance() const { return likelihood_.colours(); }

private:
    Point best_start(Point centre, double radius, TimePoint deadline);
    // Where a new track's start point came from: a person (start_at, start_in) says the target is
    // there, whatever edges it shows; the motion detector's region is searched round for the target;
    // a prediction (reacquire_at) is where the lost target should be; the filter (look_again) found
    // the lost target's looks there.
    enum class StartFrom { Person, Detector, Prediction, Filter };
    // Starts a track at m; `same_target`: a re-acquisition, keeping the target's learned looks (its
    // first contour at most reacquire_bound()); else `max_area` (px², 0: any) the most it may enclose.
    bool begin_track(Point m, double radius, StartFrom from, bool same_target, TimePoint deadline,
                     double max_area = 0.0);
    // Starts a track in a box: the box's ellipse the first contour's prior, its inside the target's looks.
    bool begin_box_track(const Box& box, TimePoint deadline);
    // The new track's first contour from m with the prior and looks set up: false if it is no target.
    bool first_contour(Point m, StartFrom from, bool same_target, TimePoint deadline, double max_area = 0.0);
    // A mover the detector found, as a new target; after a person's target is lost, only a mover
    // about its size, and the lost target's looks stay learned while none is.
    bool begin_detected(const Detection& d, TimePoint deadline);
    bool reacquire_afresh(Point m, double radius, TimePoint deadline);
    // After a loss, the filter looks for the target's looks round where it was last seen, then over
    // the whole frame, as far as within_reach(): true, and the track resumes, where it finds them
    // surely and a contour round them passes the attention check, at most reacquire_bound().
    bool look_again(TimePoint deadline);
    // Whether the lost target can have reached `p` by now: at most its radius plus the attention
    // module's largest step (attention.max_jump_px) for each frame since it was last seen.
    bool within_reach(Point p, double radius) const;
    // The largest contour that may be the lost target found again: a few times its size.
    double reacquire_bound() const;
    // This frame's contour's inside grey over the frame's mean grey.
    double inside_grey_share() const;
    void track(TimePoint deadline);
    // The attention check of this frame's contour, and, where the filter is `confident`, whether the
    // contour is still where the filter finds the target: nullptr, or why it is not the target.
    const char* check_contour(Point predicted, bool confident);
    void follow(Point last);  // the velocity, from the contour's centroid after `last`
    // This frame's contour: the last one moved by `shift` (to where the filter found the target).
    void coast_to(Point shift);
    // Whether this frame's contour encloses about the grey the target model has learned.
    bool looks_like_target() const;
    // A track standing still on something beside the mover: false (core/still_track_watch.hpp); the
    // detector is asked, on this frame against the previous one aligned by the view's drift.
    bool watch_still_track(const GreyImage& frame);
    void remember_contour();
    // The rays look with the learned colours on this frame (the likelihood map, with the motion
    // layers while the view moves), with the layers' background alone on a grey source, or without
    // when there is neither. The layers' map is moved on by `ahead`, the target's shift since the
    // last frame (by default its smoothed velocity).
    void look_with_likelihood() { look_with_likelihood(velocity_); }
    void look_with_likelihood(Point ahead);
    // After a new target's first guess of its colours (AppearanceModel::seed or seed_box): looked
    // with at once where it was seeded, else none.
    void use_seeded_colours(bool seeded);
    void forget_colours();
    // Learns the correlation filter on this frame's contour at `rate` (1: a new target's first),
    // centred on its centroid or on `at`; `located`: from the window the filter looked in this frame.
    void learn_looks(float rate, bool located, const Point* at = nullptr);
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
    ViewMotion view_motion_;      // whether the view itself moved since the previous frame
    ActiveRays rays_;
    PolarPrior prior_;
    TargetModel model_;
    TargetLikelihood likelihood_;  // the target's colours and motion layers, as the rays read them
    BoxStartPoint box_start_;     // where a box start's rays begin
    CorrelationFilter filter_;    // the target's looks, to find it before the rays look for its rim
    ChosenTarget chosen_;         // a person's target: which track is it, and its looks at the start
    FilterMatch match_;           // where it found the target this frame
    const Chroma* chroma_ = nullptr;  // the colour of the frame being processed
    Attention attention_;
    StillTrackWatch still_watch_;  // whether a track standing still is on the mover (still_track_watch.hpp)
    Contour contour_;
    std::vector<Point> last_points_;  // the previous contour, for the temporal prior
    std::vector<unsigned char> last_open_;  // its points without an edge
    std::vector<float> scratch_;
    int last_count_ = 0;
    Point last_seen_;  // the last contour's centroid
    FrameSweep sweep_;  // the whole-frame search for a lost target's looks
    double psr_tracked_ = 0.0;  // the filter's mean PSR on the target while its rim was followed
    Point velocity_;
    std::optional<Point> start_point_;
    std::optional<Box> start_box_;  // a box start: start_point_ is its centre
    bool reacquire_ = false;  // start_point_ is a re-acquisition of the last target
    std::optional<Point> external_prediction_;  // from predict_next(), for the next frame only
    bool detection_allowed_ = true;  // the caller's word: the camera was to hold still
    std::optional<Point> expected_view_;  // the caller's word: the unit's turning moved the view this far
    GreyImage aligned_previous_;     // the previous frame moved as the view moved, for differencing
    int lost_frames_ = 0;
    int untracked_frames_ = 0;  // frames since the last one with a contour
    double tracked_area_ = 0;   // area of the last contour accepted as the target
    WholeArea whole_area_;      // the target's size, for looking for it again after an occlusion
    double whole_grey_ = 0;     // its inside grey / the frame's mean grey while whole (running; 0: none yet)
    FrameResult result_;
};

}  // namespace rays
