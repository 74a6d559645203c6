// SPDX-License-Identifier: Apache-2.0
// The greedy active contour of Williams & Shah, "A fast algorithm for active contours and curvature
// estimation" (CVGIP: Image Understanding 55(1), 1992): every pass moves each point, in turn, to the
// position of least energy α·E_cont + β_i·E_curv + γ·E_image in a window round it, each term
// normalised within the window; β_i drops to 0 where the contour has a corner. Points live on the
// pixel grid, as W&S search it. Fixed memory: every buffer is sized in the constructor.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "core/clock.hpp"
#include "core/image.hpp"
#include "core/tracker_config.hpp"

namespace rays::snake {

struct SnakePoint {
    int x = 0;
    int y = 0;
};

// How one run of greedy passes ended.
struct SnakeRun {
    int iterations = 0;        // passes completed
    bool converged = false;    // fewer than moved_fraction · points moved in the last pass
    bool deadline_hit = false; // stopped because the next pass would end after the deadline
};

class GreedySnake {
public:
    static constexpr int kMinPoints = 8;
    static constexpr int kMaxNeighbourhood = 15;  // largest window side; sizes the per-window buffers

    // Buffers for up to max_points points; the tunables start at their defaults (points clamped).
    explicit GreedySnake(int max_points);

    // New settings, checked for what the algorithm needs: kMinPoints ≤ points ≤ capacity, an odd
    // neighbourhood of 3…kMaxNeighbourhood, weights ≥ 0, at least one pass, image_floor > 0. False
    // (nothing changed) otherwise. A new point count resamples the current snake along its length.
    bool configure(const SnakeTunables& tunables);
    const SnakeTunables& tunables() const { return t_; }
    int capacity() const { return static_cast<int>(points_.size()); }

    // |∇I| of the smoothed frame, computed once per frame before run().
    void set_image(const FloatImage& smoothed);
    const FloatImage& gradient_magnitude() const { return magnitude_; }

    // A circle of tunables().points points round `centre` (clamped into the frame); no corners.
    void set_circle(Point centre, double radius);
    // An ellipse of tunables().points points round `centre` with semi-axes rx, ry (clamped into the frame).
    void set_ellipse(Point centre, double rx, double ry);
    // Moves every point by `step`, rounded to whole pixels and clamped into the frame.
    void shift(Point step);

    // Greedy passes until fewer than moved_fraction · points move, max_iterations passes, or the
    // next pass would end after `deadline` (the clock is read between passes). No allocation.
    SnakeRun run(const Clock& clock, TimePoint deadline);

    int size() const { return n_; }
    const SnakePoint& point(int i) const { return points_[static_cast<std::size_t>(i)]; }
    bool corner(int i) const { return corner_[static_cast<std::size_t>(i)] != 0; }

private:
    static constexpr int kMaxWindow = kMaxNeighbourhood * kMaxNeighbourhood;

    int pass();  // one greedy pass over every point; returns how many moved
    void find_corners();
    void resample(int count);
    double mean_spacing() const;

    SnakeTunables t_;
    int n_ = 0;
    std::vector<SnakePoint> points_;     // capacity entries, n_ in use, a closed ring
    std::vector<SnakePoint> resampled_;  // scratch for resample()
    std::vector<std::uint8_t> corner_;   // 1 where β_i = 0
    std::vector<double> curvature_;      // W&S curvature estimate per point
    std::array<double, kMaxWindow> cont_{}, curv_{}, image_{};
    std::array<bool, kMaxWindow> inside_{};
    FloatImage magnitude_;
};

}  // namespace rays::snake
