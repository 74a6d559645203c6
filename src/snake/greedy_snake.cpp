// SPDX-License-Identifier: Apache-2.0
#include "snake/greedy_snake.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "snake/image_gradient.hpp"

namespace rays::snake {
namespace {

SnakePoint on_grid(double x, double y) {
    const auto clamp = [](double v) { return static_cast<int>(std::clamp(std::lround(v), 0L, kFrameSize - 1L)); };
    return {clamp(x), clamp(y)};
}

double distance(SnakePoint a, SnakePoint b) { return std::hypot(a.x - b.x, a.y - b.y); }

}  // namespace

GreedySnake::GreedySnake(int max_points)
    : points_(static_cast<std::size_t>(std::max(max_points, kMinPoints))),
      resampled_(points_.size()),
      corner_(points_.size()),
      curvature_(points_.size()) {
    t_.points = std::min(t_.points, capacity());
}

bool GreedySnake::configure(const SnakeTunables& tunables) {
    const SnakeTunables& t = tunables;
    const bool valid = t.points >= kMinPoints && t.points <= capacity() && t.neighbourhood >= 3 &&
                       t.neighbourhood <= kMaxNeighbourhood && t.neighbourhood % 2 == 1 && t.alpha >= 0 &&
                       t.beta >= 0 && t.gamma >= 0 && t.max_iterations >= 1 && t.image_floor > 0;
    if (!valid) return false;
    if (n_ > 0 && t.points != n_) resample(t.points);
    t_ = t;
    return true;
}

void GreedySnake::set_image(const FloatImage& smoothed) { snake::gradient_magnitude(smoothed, magnitude_); }

void GreedySnake::set_circle(Point centre, double radius) { set_ellipse(centre, radius, radius); }

void GreedySnake::set_ellipse(Point centre, double rx, double ry) {
    n_ = t_.points;
    for (int i = 0; i < n_; ++i) {
        const double a = 2.0 * std::numbers::pi * i / n_;
        points_[i] = on_grid(centre.x + rx * std::cos(a), centre.y + ry * std::sin(a));
    }
    std::fill(corner_.begin(), corner_.end(), std::uint8_t{0});
}

void GreedySnake::shift(Point step) {
    for (int i = 0; i < n_; ++i) {
        SnakePoint& p = points_[i];
        p = on_grid(p.x + step.x, p.y + step.y);
    }
}

double GreedySnake::mean_spacing() const {
    double sum = 0.0;
    for (int i = 0; i < n_; ++i) sum += distance(points_[i], points_[(i + 1) % n_]);
    return sum / n_;
}

int GreedySnake::pass() {
    const int half = t_.neighbourhood / 2;
    const int side = t_.neighbourhood;
    const int centre = half * side + half;  // the window index of the point's own position
    const double spacing = mean_spacing();  // d̄, the mean distance between neighbours
    int moved = 0;
    for (int i = 0; i < n_; ++i) {
        // v_{i-1} is the already moved predecessor, as in W&S's single sweep.
        const SnakePoint prev = points_[(i + n_ - 1) % n_];
        const SnakePoint next = points_[(i + 1) % n_];
        SnakePoint& v = points_[i];
        double max_cont = 0.0, max_curv = 0.0;
        double min_mag = magnitude_.at(v.x, v.y), max_mag = min_mag;
        for (int dy = -half; dy <= half; ++dy)
            for (int dx = -half; dx <= half; ++dx) {
                const int k = (dy + half) * side + dx + half;
                const int x = v.x + dx, y = v.y + dy;
                inside_[k] = x >= 0 && x < kFrameSize && y >= 0 && y < kFrameSize;
                if (!inside_[k]) continue;
                // W&S's E_cont: |d̄ − |v_i − v_{i−1}||, which keeps the points evenly spaced without
                // shrinking the contour as the first-order term |v_i − v_{i−1}|² of Kass et al. does.
                cont_[k] = std::abs(spacing - std::hypot(x - prev.x, y - prev.y));
                // E_curv: |v_{i−1} − 2v_i + v_{i+1}|², the second difference.
                const double cx = prev.x - 2.0 * x + next.x, cy = prev.y - 2.0 * y + next.y;
                curv_[k] = cx * cx + cy * cy;
                // E_image: −|∇I|, normalised below.
                image_[k] = magnitude_.at(x, y);
                max_cont = std::max(max_cont, cont_[k]);
                max_curv = std::max(max_curv, curv_[k]);
                min_mag = std::min(min_mag, image_[k]);
                max_mag = std::max(max_mag, image_[k]);
            }
        // W&S normalise E_cont and E_curv by their largest value in the window and E_image as
        // (min − mag) / (max − min), with max − min held at least image_floor so that a flat
        // neighbourhood does not turn noise into a strong pull.
        const double beta = corner_[i] ? 0.0 : t_.beta;
        const double a = max_cont > 0 ? t_.alpha / max_cont : 0.0;
        const double b = max_curv > 0 ? beta / max_curv : 0.0;
        const double g = t_.gamma / std::max(max_mag - min_mag, t_.image_floor);
        const auto energy = [&](int k) { return a * cont_[k] + b * curv_[k] + g * (min_mag - image_[k]); };
        int best = centre;  // ties keep the point where it is
        double best_energy = energy(centre);
        for (int k = 0; k < side * side; ++k)
            if (inside_[k] && energy(k) < best_energy) {
                best = k;
                best_energy = energy(k);
            }
        if (best != centre) {
            v = {v.x + best % side - half, v.y + best / side - half};
            ++moved;
        }
    }
    return moved;
}

void GreedySnake::find_corners() {
    // W&S's curvature estimate c_i = |u_i/|u_i| − u_{i+1}/|u_{i+1}||², u_i = v_i − v_{i−1}; β_i = 0
    // where c_i is a local maximum above corner_curvature on an edge stronger than corner_edge.
    for (int i = 0; i < n_; ++i) {
        const SnakePoint p = points_[(i + n_ - 1) % n_];
        const SnakePoint v = points_[i];
        const SnakePoint q = points_[(i + 1) % n_];
        const double la = std::max(distance(p, v), 1e-9), lb = std::max(distance(v, q), 1e-9);
        const double ex = (v.x - p.x) / la - (q.x - v.x) / lb, ey = (v.y - p.y) / la - (q.y - v.y) / lb;
        curvature_[i] = ex * ex + ey * ey;
    }
    for (int i = 0; i < n_; ++i) {
        const double c = curvature_[i];
        const SnakePoint v = points_[i];
        const bool corner = c > curvature_[(i + n_ - 1) % n_] &&
                            c > curvature_[(i + 1) % n_] && c > t_.corner_curvature &&
                            magnitude_.at(v.x, v.y) > t_.corner_edge;
        corner_[i] = corner ? 1 : 0;
    }
}

SnakeRun GreedySnake::run(const Clock& clock, TimePoint deadline) {
    SnakeRun run;
    if (n_ == 0) return run;
    const TimePoint start = clock.now();
    TimePoint now = start;
    for (int it = 0; it < t_.max_iterations; ++it) {
        if (it > 0) now = clock.now();
        const auto per_pass = it > 0 ? (now - start) / it : MonoClock::duration::zero();
        if (now + per_pass > deadline) {
            run.deadline_hit = true;
            break;
        }
        const int moved = pass();
        find_corners();
        ++run.iterations;
        if (moved == 0 || moved < t_.moved_fraction * n_) {
            run.converged = true;
            break;
        }
    }
    return run;
}

void GreedySnake::resample(int count) {
    // Evenly along the closed polygon's length, so a new point count keeps the shape.
    const double length = mean_spacing() * n_;
    int seg = 0;
    double seg_start = 0.0;  // length along the polygon where segment seg begins
    for (int k = 0; k < count; ++k) {
        const double at = length * k / count;
        double seg_length = distance(points_[seg], points_[(seg + 1) % n_]);
        while (seg + 1 < n_ && seg_start + seg_length < at) {
            seg_start += seg_length;
            ++seg;
            seg_length = distance(points_[seg], points_[(seg + 1) % n_]);
        }
        const SnakePoint a = points_[seg], b = points_[(seg + 1) % n_];
        const double f = seg_length > 0 ? (at - seg_start) / seg_length : 0.0;
        resampled_[k] = on_grid(a.x + f * (b.x - a.x), a.y + f * (b.y - a.y));
    }
    std::copy_n(resampled_.begin(), count, points_.begin());
    std::fill(corner_.begin(), corner_.end(), std::uint8_t{0});
    n_ = count;
}

}  // namespace rays::snake
