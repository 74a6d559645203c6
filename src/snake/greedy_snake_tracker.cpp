// SPDX-License-Identifier: Apache-2.0
#include "snake/greedy_snake_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "snake/snake_contour.hpp"

namespace rays {
namespace {

constexpr double kStartRadiusPx = 10.0;  // first guess of the target's radius at a start point
constexpr int kStartCandidates = 6;      // start circles tried round a detected region's centre
constexpr double kVelocityRate = 0.7;    // weight of the newest centroid step in the velocity

}  // namespace

GreedySnakeTracker::GreedySnakeTracker(const TrackerConfig& config, const Clock& clock)
    : clock_(clock),
      capacity_(config.capacity),
      snake_(config.capacity.max_snake_points),
      contour_(snake::snake_contour_capacity(config.capacity)) {
    set_tunables(config.tunables);
    detector_.reset(tunables_.detect);
}

bool GreedySnakeTracker::set_tunables(const TrackerTunables& tunables) {
    if (!snake_.configure(tunables.snake)) return false;
    tunables_ = tunables;
    smoother_.set_sigma(tunables_.snake.sigma_px);
    return true;
}

void GreedySnakeTracker::start_at(Point m) {
    start_point_ = m;
    start_box_.reset();
}

bool GreedySnakeTracker::start_in(const Box& box) {
    if (box_problem(box) != nullptr) return false;
    start_point_ = box.centre();
    start_box_ = box;
    return true;
}

void GreedySnakeTracker::release() {
    result_.state = TrackState::Detecting;
    result_.has_contour = false;
    start_point_.reset();
    start_box_.reset();
}

void GreedySnakeTracker::reinit() {
    release();
    detector_.reset(tunables_.detect);
}

void GreedySnakeTracker::extract(TimePoint deadline) {
    const snake::SnakeRun run = snake_.run(clock_, deadline);
    snake::write_snake_contour(snake_, smoothed_, run, contour_);
}

Point GreedySnakeTracker::best_start(Point centre, double radius, TimePoint deadline) {
    // Frame differencing often finds only one crescent of a slow object, so its centre may lie on the
    // rim (as in Tracker::best_start). Snakes started round the region's centre and round points
    // about one radius from it are compared; the one on the strongest edges, of a plausible size
    // and edge coverage, gives the start.
    Point best = centre;
    double best_score = 0.0;
    for (int k = -1; k < kStartCandidates; ++k) {
        const double a = 2.0 * std::numbers::pi * k / kStartCandidates;
        const Point m = k < 0 ? centre : Point{centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)};
        snake_.set_circle(m, tunables_.snake.initial_radius_factor * radius);
        extract(deadline);
        attention_.reset();
        if (attention_.check(contour_, contour_.centroid, tunables_.attention) != nullptr) continue;
        double score = 0.0;
        for (int i = 0; i < contour_.size; ++i) score += std::abs(contour_.points[i].grad);
        if (score > best_score) {
            best_score = score;
            best = m;
        }
    }
    return best;
}

bool GreedySnakeTracker::begin_track(Point m, double radius, bool search, TimePoint deadline) {
    // Williams & Shah have no balloon force: the start circle lies outside the target and the
    // curvature and image terms pull it in onto the edges.
    if (search) m = best_start(m, radius, deadline);
    snake_.set_circle(m, tunables_.snake.initial_radius_factor * radius);
    return first_contour(deadline);
}

bool GreedySnakeTracker::begin_box_track(const Box& box, TimePoint deadline) {
    snake_.set_ellipse(box.centre(), 0.5 * box.w, 0.5 * box.h);
    return first_contour(deadline);
}

bool GreedySnakeTracker::first_contour(TimePoint deadline) {
    attention_.reset();
    velocity_ = {};
    extract(deadline);
    return attention_.check(contour_, contour_.centroid, tunables_.attention) == nullptr;
}

void GreedySnakeTracker::track(TimePoint deadline) {
    // The previous contour moved by the prediction is where the target should be now: an outside
    // prediction (predict_next) if given, else the constant-velocity guess.
    const Point last = contour_.centroid;
    Point step = tunables_.predict ? velocity_ : Point{};
    if (external_prediction_) step = {external_prediction_->x - last.x, external_prediction_->y - last.y};
    const Point predicted{last.x + step.x, last.y + step.y};
    result_.predicted = predicted;
    snake_.shift(step);
    extract(deadline);
    if (const char* reason = attention_.check(contour_, predicted, tunables_.attention)) {
        result_.state = TrackState::Lost;
        result_.has_contour = false;
        result_.lost_reason = reason;
        lost_frames_ = 0;
        return;
    }
    const Point moved{contour_.centroid.x - last.x, contour_.centroid.y - last.y};
    velocity_ = {velocity_.x + kVelocityRate * (moved.x - velocity_.x), velocity_.y + kVelocityRate * (moved.y - velocity_.y)};
}

const FrameResult& GreedySnakeTracker::process(const GreyImage& frame, const Chroma&, TimePoint deadline) {
    ++result_.frame;
    result_.lost_reason = nullptr;
    result_.detection = {};
    smoother_.smooth(frame, smoothed_);
    snake_.set_image(smoothed_);

    if (result_.state == TrackState::Lost && ++lost_frames_ >= tunables_.attention.lost_frames)
        result_.state = TrackState::Detecting;

    if (result_.state == TrackState::Tracking) {
        track(deadline);
    } else if (result_.state == TrackState::Detecting) {
        bool found = false;
        if (start_point_) {
            found = start_box_ ? begin_box_track(*start_box_, deadline)
                               : begin_track(*start_point_, kStartRadiusPx, false, deadline);
            start_point_.reset();
            start_box_.reset();
        } else if (has_previous_ && detection_allowed_) {
            result_.detection = detector_.detect(previous_, frame, tunables_.detect);
            const Detection& d = result_.detection;
            if (d.found) found = begin_track(d.centre, std::max(d.radius_px, kStartRadiusPx * 0.6), true, deadline);
        }
        result_.state = found ? TrackState::Tracking : TrackState::Detecting;
        result_.has_contour = found;
        result_.predicted = contour_.centroid;
    }
    external_prediction_.reset();
    previous_ = frame;
    has_previous_ = true;
    return result_;
}

}  // namespace rays
