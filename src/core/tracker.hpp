// The tracking state machine: detecting → tracking → lost → detecting (§4.1), with the motion
// detector for initialisation, active rays for the contour, the attention module for loss, and a
// constant-velocity prediction of the reference point (the paper's future work).
#pragma once
#include <optional>
#include <vector>

#include "core/active_rays.hpp"
#include "core/attention.hpp"
#include "core/clock.hpp"
#include "core/gaussian_smoother.hpp"
#include "core/motion_detector.hpp"

namespace rays {

enum class TrackState { Detecting, Tracking, Lost };
const char* to_string(TrackState s);

struct FrameResult {
    long frame = -1;
    TrackState state = TrackState::Detecting;
    bool has_contour = false;      // true while tracking
    Point predicted;               // where m was expected this frame
    Detection detection;           // the motion detector's output, on frames it ran
    const char* lost_reason = nullptr;
};

class Tracker {
public:
    // Sizes every buffer from config.capacity; nothing is allocated after this.
    Tracker(const TrackerConfig& config, const Clock& clock);

    // Applies new tunables within the capacities without allocating; false (nothing changed) if invalid.
    bool set_tunables(const TrackerTunables& tunables);
    const TrackerTunables& tunables() const { return tunables_; }
    const TrackerCapacity& capacity() const { return capacity_; }

    void start_at(Point m);  // a start point from the user replaces detection on the next frame
    void release();          // drop the target and detect again
    void reinit();           // release and restart the detector's threshold adaptation

    // Processes one frame; refinement stops before `deadline`. No allocation, no exceptions.
    const FrameResult& process(const GreyImage& frame, TimePoint deadline);

    TrackState state() const { return result_.state; }
    const FrameResult& result() const { return result_; }
    const Contour& contour() const { return contour_; }
    const ActiveRays& rays() const { return rays_; }

private:
    Point best_start(Point centre, double radius, TimePoint deadline);
    bool begin_track(Point m, double radius, bool search, TimePoint deadline);
    void track(TimePoint deadline);
    void remember_contour();

    const Clock& clock_;
    TrackerCapacity capacity_;
    TrackerTunables tunables_;
    GaussianSmoother smoother_;
    FloatImage smoothed_;
    GreyImage previous_;
    bool has_previous_ = false;
    MotionDetector detector_;
    ActiveRays rays_;
    PolarPrior prior_;
    TargetModel model_;
    Attention attention_;
    Contour contour_;
    std::vector<Point> last_points_;  // the previous contour, for the temporal prior
    std::vector<float> scratch_;
    int last_count_ = 0;
    Point velocity_;
    std::optional<Point> start_point_;
    int lost_frames_ = 0;
    FrameResult result_;
};

}  // namespace rays
