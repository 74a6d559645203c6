// SPDX-License-Identifier: Apache-2.0
// One ray's 1-D search (§2.2, §2.4): sample the smoothed image along the ray (eq. 6), take the
// derivative of the profile (eq. 7, 12) and keep up to K contour hypotheses (eq. 13).
#pragma once
#include <algorithm>
#include <vector>

#include "core/appearance_model.hpp"
#include "core/image.hpp"
#include "core/tracker_config.hpp"

namespace rays {

struct Hypothesis {
    float lambda = 0;       // distance from m along the ray, px (sub-sample refined)
    float grad = 0;         // dρ/dλ at lambda, grey/px; negative where the outside is darker
    float inside_mean = 0;  // mean grey of the samples on the outer two thirds of the way from m to the edge
    float inside_msq = 0;   // mean of their squares (for the region term's spread)
    float outside_mean = -1;  // mean grey of a short band just outside the edge; < 0 when off the image
    float foreground_step = 0;  // foreground just inside − just outside (−1 … 1; 0 without a background)
    // With a colour model: how much less likely the ray's colours make a rim here than at the best
    // place along the ray, in nats (≥ 0; 0 without a model).
    float appearance = 0;
};

// How far a hypothesis's inside statistics describe the target: an edge within a few px of m has its
// inside samples blurred into the rim by the smoothing, so they say little (0 at ≤ 3 px, 1 from 6 px).
inline float inside_reliability(float lambda) { return std::clamp((lambda - 3.0f) / 3.0f, 0.0f, 1.0f); }

class RayProfiler {
public:
    explicit RayProfiler(const TrackerCapacity& capacity);

    // Takes the sampling settings; returns false when they need more samples than the capacity.
    bool configure(const RaysTunables& t);

    // Samples the ray from m in direction (c, s) with bilinear interpolation up to λ = lambda_limit
    // (and the image border) and writes at most K hypotheses at λ ≥ lambda_from, strongest first,
    // into `out`. Returns how many. Also reports the last λ sampled. With a `foreground`
    // (BackgroundModel), an edge where the ray leaves it ranks as if up to twice as strong. With a
    // colour `likelihood` (AppearanceModel), the place where the ray's colours best split into target
    // then background is always among the hypotheses, edge or not, and each hypothesis says how far
    // its λ falls short of that split (Hypothesis::appearance).
    int shoot(const FloatImage& image, const FloatImage* foreground, const LikelihoodMap* likelihood, Point m,
              double c, double s, float lambda_from, float lambda_limit, Hypothesis* out, float& lambda_end);

    // After a shoot() with a colour likelihood: Hypothesis::appearance for a rim at `lambda` on that
    // ray (0 without a likelihood).
    float appearance_at(float lambda) const;

private:
    int samples_ = 0;
    int shot_samples_ = 0, split_ = -1;  // the last shoot()'s samples and colour split (-1: none)
    int k_ = 0;
    float lambda_min_ = 0, step_ = 1, floor_ = 0, separation_ = 0;
    std::vector<float> profile_, grad_, prefix_, prefix_sq_, foreground_step_, rank_, log_odds_, log_odds_sum_;
    std::vector<int> candidates_;
};

}  // namespace rays
