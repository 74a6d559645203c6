// SPDX-License-Identifier: Apache-2.0
// The greedy-snake baseline behind the same interface as active rays: the state machine of
// core/tracker.hpp (detecting → tracking → lost → detecting) with the motion detector to start,
// the attention module for loss and a constant-velocity prediction, but the contour from the
// greedy snake of Williams & Shah (snake/greedy_snake.hpp) instead of active rays. A new snake is
// a circle of initial_radius_factor × the detected radius, which shrinks onto the target's edges,
// round the detected centre or round a point one radius from it (the detector often finds only
// one crescent of a slow target; see best_start). A box start's snake is the box's inscribed
// ellipse. Each frame starts from the previous snake moved by the prediction.
#pragma once
#include <optional>

#include "core/attention.hpp"
#include "core/clock.hpp"
#include "core/contour_tracker.hpp"
#include "core/gaussian_smoother.hpp"
#include "core/motion_detector.hpp"
#include "snake/greedy_snake.hpp"

namespace rays {

class GreedySnakeTracker final : public ContourTracker {
public:
    // Sizes every buffer from config.capacity (max_snake_points); nothing is allocated after this.
    GreedySnakeTracker(const TrackerConfig& config, const Clock& clock);

    const char* method() const override { return "snake"; }
    // Checks tunables.snake (snake::GreedySnake::configure); false (nothing changed) if invalid.
    bool set_tunables(const TrackerTunables& tunables) override;
    const TrackerTunables& tunables() const { return tunables_; }
    const TrackerCapacity& capacity() const { return capacity_; }

    // The next frame starts a snake round m (a circle of initial_radius_factor × 10 px).
    void start_at(Point m) override;
    // The next frame starts a snake on the box's inscribed ellipse.
    bool start_in(const Box& box) override;
    // The snake keeps no model of the target's looks: a re-acquisition is a fresh start.
    void reacquire_at(Point m) override { start_at(m); }
    void release() override;
    void reinit() override;
    void predict_next(Point m) override { external_prediction_ = m; }
    void allow_detection(bool allowed) override { detection_allowed_ = allowed; }
    void expect_view_shift(std::optional<Point>) override {}  // the snake does not use it

    // Processes one frame (grey alone: `chroma` is not read); the greedy passes stop before
    // `deadline`. No allocation, no exceptions.
    using ContourTracker::process;
    const FrameResult& process(const GreyImage& frame, const Chroma& chroma, TimePoint deadline) override;

    TrackState state() const { return result_.state; }
    const FrameResult& result() const override { return result_; }
    const Contour& contour() const override { return contour_; }
    const snake::GreedySnake& snake() const { return snake_; }

private:
    Point best_start(Point centre, double radius, TimePoint deadline);
    bool begin_track(Point m, double radius, bool search, TimePoint deadline);
    bool begin_box_track(const Box& box, TimePoint deadline);
    bool first_contour(TimePoint deadline);  // from the snake as set up: false if it is no target
    void track(TimePoint deadline);
    void extract(TimePoint deadline);  // greedy passes on the current frame, into contour_

    const Clock& clock_;
    TrackerCapacity capacity_;
    TrackerTunables tunables_;
    GaussianSmoother smoother_;
    FloatImage smoothed_;
    GreyImage previous_;
    bool has_previous_ = false;
    MotionDetector detector_;
    snake::GreedySnake snake_;
    Attention attention_;
    Contour contour_;
    Point velocity_;
    std::optional<Point> start_point_;
    std::optional<Box> start_box_;  // a box start: start_point_ is its centre
    std::optional<Point> external_prediction_;  // from predict_next(), for the next frame only
    bool detection_allowed_ = true;
    int lost_frames_ = 0;
    FrameResult result_;
};

}  // namespace rays
