// SPDX-License-Identifier: Apache-2.0
#include "core/ray_hypotheses.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/frame_kernel.hpp"
#include "core/ray_sampler.hpp"

namespace rays {
namespace {

constexpr float kEdgeMarginPx = 1.0f;  // samples this close to an edge belong to neither side
constexpr float kOutsideBandPx = 4.0f; // the band that should look like background
constexpr float kForegroundReachPx = 2.0f;  // the foreground is read this far inside and outside an edge
constexpr float kRimStep = 0.5f;            // an edge whose foreground drops this much is a rim
constexpr float kSplitReachPx = 1.5f;       // an edge this near the colour split stands for it

}  // namespace

RayProfiler::RayProfiler(const TrackerCapacity& capacity)
    : profile_(whole_lanes(capacity.max_samples)),
      grad_(capacity.max_samples + kLanes),
      prefix_(capacity.max_samples + 1),
      prefix_sq_(capacity.max_samples + 1),
      foreground_step_(capacity.max_samples),
      rank_(capacity.max_samples),
      log_odds_(whole_lanes(capacity.max_samples)),
      log_odds_sum_(capacity.max_samples + 1 + kLanes),
      candidates_(capacity.max_samples) {}

bool RayProfiler::configure(const RaysTunables& t) {
    const int n = static_cast<int>(std::floor((t.lambda_max_px - t.lambda_min_px) / t.step_px)) + 1;
    if (n < 3 || n > static_cast<int>(profile_.size())) return false;
    samples_ = n;
    k_ = t.hypotheses;
    lambda_min_ = static_cast<float>(t.lambda_min_px);
    step_ = static_cast<float>(t.step_px);
    floor_ = static_cast<float>(t.edge_floor);
    separation_ = static_cast<float>(t.hypothesis_separation_px);
    return true;
}

RAYS_FRAME_KERNEL
int RayProfiler::shoot(const FloatImage& image, const FloatImage* foreground, const LikelihoodMap* likelihood,
                       Point m, double c, double s, float lambda_from, float lambda_limit, Hypothesis* out,
                       float& lambda_end) {
    constexpr double last = kFrameSize - 1;
    // The ray ends where it leaves the image: λ ≤ the distance to the border along (c, s).
    double reach = lambda_limit;
    if (c > 1e-9) reach = std::min(reach, (last - m.x) / c);
    if (c < -1e-9) reach = std::min(reach, -m.x / c);
    if (s > 1e-9) reach = std::min(reach, (last - m.y) / s);
    if (s < -1e-9) reach = std::min(reach, -m.y / s);
    const int n = std::clamp(static_cast<int>(std::floor((reach - lambda_min_) / step_ + 1e-6)) + 1, 0, samples_);
    const float cx = static_cast<float>(c), sy = static_cast<float>(s);
    // eq. 6, bilinear; `reach` keeps every sample inside the image.
    const float x_first = static_cast<float>(m.x) + lambda_min_ * cx, y_first = static_cast<float>(m.y) + lambda_min_ * sy;
    const float dx = step_ * cx, dy = step_ * sy;
    sample_ray(image, likelihood, x_first, y_first, dx, dy, n, profile_.data(), log_odds_.data());
    float sum = 0.0f, sum_sq = 0.0f;  // the running sums, in registers
    prefix_[0] = prefix_sq_[0] = log_odds_sum_[0] = 0.0f;
    for (int j = 0; j < n; ++j) {
        const float v = profile_[j];
        prefix_[j + 1] = sum += v;  // running sums make the region term O(1) per hypothesis
        prefix_sq_[j + 1] = sum_sq += v * v;
    }
    // With colour: the running sum of the log-odds the colour split is found from (below).
    if (likelihood != nullptr) {
        float log_odds = 0.0f;
        for (int j = 0; j < n; ++j) log_odds_sum_[j + 1] = log_odds += log_odds_[j];
    }
    lambda_end = lambda_min_ + static_cast<float>(std::max(0, n - 1)) * step_;
    shot_samples_ = n;
    split_ = -1;
    if (n < 3) return 0;

    // eq. 7/12: H = −|∂ρ/∂λ|², central differences; candidates are local maxima of |∂ρ/∂λ|.
    const float inv2step = 0.5f / step_;
    int nc = 0;
    grad_[0] = grad_[n - 1] = 0.0f;
    for (int j = 1; j < n - 1; ++j) grad_[j] = (profile_[j + 1] - profile_[j - 1]) * inv2step;
    // With a foreground: how much of it the ray leaves at sample j (read only at the candidates).
    const int fg_reach = std::max(1, static_cast<int>(std::lround(kForegroundReachPx / step_)));
    auto leaves_foreground = [&](int j) {
        const auto at = [&](int k) {  // at the nearest pixel (inside the image, as sample k is)
            const auto t = static_cast<float>(k);
            return foreground->at(static_cast<int>(x_first + t * dx + 0.5f), static_cast<int>(y_first + t * dy + 0.5f));
        };
        return at(std::max(0, j - fg_reach)) - at(std::min(n - 1, j + fg_reach));
    };
    const int first = std::max(1, static_cast<int>(std::ceil((lambda_from - lambda_min_) / step_ - 1e-6f)));
    // Without branches, four samples at a time: whether a sample is a maximum is as good as random,
    // a branch on it mispredicted. Each is written as the next candidate and counted where it is one.
    for (int j = first; j < n - 1; j += kLanes) {
        const Lanes a = abs_lanes(load_lanes(&grad_[j]));
        const LaneIndex maximum = (a >= floor_) & (a >= abs_lanes(load_lanes(&grad_[j - 1]))) &
                                  (a > abs_lanes(load_lanes(&grad_[j + 1]))) & (j + kLaneOffsets < n - 1);
        for (int l = 0; l < kLanes; ++l) {
            candidates_[nc] = j + l;
            nc -= maximum[l];  // a true lane is −1
        }
    }
    for (int ci = 0; ci < nc; ++ci) {
        const int j = candidates_[ci];
        foreground_step_[j] = foreground != nullptr ? leaves_foreground(j) : 0.0f;
        rank_[j] = std::abs(grad_[j]) * (1.0f + std::max(0.0f, foreground_step_[j]));
    }
    // eq. 13: hypotheses in order of decreasing |∂ρ/∂λ|² (an edge out of the foreground counting up
    // to twice); eq. 15's wish for well-separated hypotheses is kept as a minimum separation between them.
    std::sort(candidates_.begin(), candidates_.begin() + nc, [&](int a, int b) { return rank_[a] > rank_[b]; });
    // The edge where the ray most clearly leaves the foreground is kept however weak it is: a target
    // about as grey as its background has weak edges, and stronger ones of the background crowd it out.
    int rim = -1;
    for (int ci = 0; ci < nc; ++ci) {
        const float step = foreground_step_[candidates_[ci]];
        if (step >= kRimStep && (rim < 0 || step > foreground_step_[candidates_[rim]])) rim = ci;
    }
    if (rim > 0) std::rotate(candidates_.begin(), candidates_.begin() + rim, candidates_.begin() + rim + 1);

    // The colour split: the rim that makes samples 0 … b−1 the target and b … n−1 the background is
    // the most likely one where the log-odds summed from m, S(b), is largest (the ray's 1-D region
    // competition; a texture-based energy on the 1-D signal, as the paper's future work proposes).
    // Its nearest edge candidate goes first; with none near, the split itself is a hypothesis.
    int split = -1;
    if (likelihood != nullptr) {
        // Boundary b lies between samples b − 1 and b; the first b where S(b) is largest, found lane
        // by lane (each lane's first largest), then the earliest of the lanes' where they tie.
        Lanes most = -std::numeric_limits<float>::infinity() + Lanes{};
        LaneIndex at{};
        for (int b = first; b <= n; b += kLanes) {
            const LaneIndex index = b + kLaneOffsets;
            const Lanes s_b = index <= n ? load_lanes(&log_odds_sum_[b]) : most;
            const LaneIndex more = s_b > most;
            most = more ? s_b : most;
            at = more ? index : at;
        }
        split = first;  // (a ray that ends before `first` keeps that)
        if (first <= n) {
            float top = most[0];
            for (int l = 1; l < kLanes; ++l) top = std::max(top, most[l]);
            split = n;
            for (int l = 0; l < kLanes; ++l)
                if (most[l] == top) split = std::min(split, at[l]);
        }
        const auto half_steps = [&](int j) { return std::abs(2 * j + 1 - 2 * split); };  // edge j to the split
        int near = -1;
        for (int ci = 0; ci < nc; ++ci) {
            const int j = candidates_[ci];
            if (0.5f * step_ * static_cast<float>(half_steps(j)) > kSplitReachPx) continue;
            if (near < 0 || half_steps(j) < half_steps(candidates_[near])) near = ci;
        }
        split_ = split;
        if (near < 0 && likelihood->split_rims) {  // no edge there: the split's own sample, however weak its gradient
            near = nc;
            candidates_[nc++] = std::clamp(split, first, n - 2);
            foreground_step_[candidates_[near]] = 0.0f;
        }
        if (near >= 0) std::rotate(candidates_.begin(), candidates_.begin() + near, candidates_.begin() + near + 1);
    }
    const int margin = static_cast<int>(std::ceil(kEdgeMarginPx / step_));
    const int band = std::max(1, static_cast<int>(std::lround(kOutsideBandPx / step_)));
    int kept = 0;
    for (int ci = 0; ci < nc && kept < k_; ++ci) {
        const int j = candidates_[ci];
        const float a = std::abs(grad_[j - 1]), b = std::abs(grad_[j]), cc = std::abs(grad_[j + 1]);
        const float denom = a - 2.0f * b + cc;
        const float offset = denom < 0.0f ? std::clamp(0.5f * (a - cc) / denom, -0.5f, 0.5f) : 0.0f;
        const float lam = lambda_min_ + (static_cast<float>(j) + offset) * step_;
        bool separated = true;
        for (int h = 0; h < kept; ++h) separated &= std::abs(out[h].lambda - lam) >= separation_;
        if (!separated) continue;
        Hypothesis& hyp = out[kept++];
        hyp.lambda = lam;
        hyp.grad = grad_[j];
        hyp.foreground_step = foreground_step_[j];
        hyp.appearance = appearance_at(lam);
        // The inside: samples [in_end / 3, in_end), the outer two thirds of the way to the edge. Near m
        // the ray may start on something thin in front of the target (a pole across its middle),
        // and the part next to the rim is what tells the target's inside from the background.
        const int in_end = std::max(1, j - margin), in_begin = in_end / 3;
        const auto inside = static_cast<float>(in_end - in_begin);
        hyp.inside_mean = (prefix_[in_end] - prefix_[in_begin]) / inside;
        hyp.inside_msq = (prefix_sq_[in_end] - prefix_sq_[in_begin]) / inside;
        const int o0 = std::min(n, j + margin), o1 = std::min(n, j + margin + band);
        hyp.outside_mean = o1 > o0 ? (prefix_[o1] - prefix_[o0]) / static_cast<float>(o1 - o0) : -1.0f;
    }
    return kept;
}

float RayProfiler::appearance_at(float lambda) const {
    if (split_ < 0) return 0.0f;
    // A rim at λ splits the ray after sample (λ − λ_min) / step: between the sums either side of it.
    const float at = std::clamp((lambda - lambda_min_) / step_ + 0.5f, 0.0f, static_cast<float>(shot_samples_));
    const int b = std::min(static_cast<int>(at), shot_samples_ - 1);
    const float f = at - static_cast<float>(b);
    return log_odds_sum_[split_] - (log_odds_sum_[b] + f * (log_odds_sum_[b + 1] - log_odds_sum_[b]));
}

}  // namespace rays
