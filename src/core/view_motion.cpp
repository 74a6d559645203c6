// SPDX-License-Identifier: Apache-2.0
#include "core/view_motion.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr float kFlatSpread = 0.5f;  // grey: a profile flatter than this (a clear sky) tells no shift
// Of two normalised profiles, the mean squared difference where they match: 2 (1 − correlation).
// Bands whose best match is worse (correlation below 1/2: noise, or a view that changed there)
// tell no shift.
constexpr double kMatchCost = 1.0;
constexpr double kDriftClear = 2.0;  // standard errors: a still view's drift is taken where it stands this clear of 0

// Removes the profile's mean and scales it to unit spread (an exposure change is not motion);
// false when it is too flat to tell a shift.
bool normalise(std::array<float, kFrameSize>& p) {
    double sum = 0.0, squares = 0.0;
    for (float v : p) {
        sum += v;
        squares += static_cast<double>(v) * v;
    }
    const double mean = sum / kFrameSize;
    const double spread = std::sqrt(std::max(0.0, squares / kFrameSize - mean * mean));
    if (spread < kFlatSpread) return false;
    for (float& v : p) v = static_cast<float>((v - mean) / spread);
    return true;
}

}  // namespace

RAYS_FRAME_KERNEL
std::optional<double> ViewMotion::best_shift(const Profile& before, const Profile& now) {
    // cost(s): mean squared difference where now(i) and before(i − s) overlap. Every shift's sum
    // runs over i in order, all shifts side by side: independent chains of adds, not one long one.
    // Near the ends only some shifts overlap; in between all do, in a loop of fixed length.
    std::array<double, 2 * kMaxShiftPx + 1> cost{};
    auto add = [&](int i, int s_from, int s_to) {
        for (int s = s_from; s <= s_to; ++s) {
            const double d = now[i] - before[i - s];
            cost[s + kMaxShiftPx] += d * d;
        }
    };
    for (int i = 0; i < kMaxShiftPx; ++i) add(i, -kMaxShiftPx, i);
    for (int i = kMaxShiftPx; i < kFrameSize - kMaxShiftPx; ++i) add(i, -kMaxShiftPx, kMaxShiftPx);
    for (int i = kFrameSize - kMaxShiftPx; i < kFrameSize; ++i) add(i, i - (kFrameSize - 1), kMaxShiftPx);
    for (int s = -kMaxShiftPx; s <= kMaxShiftPx; ++s) cost[s + kMaxShiftPx] /= kFrameSize - std::abs(s);
    const int best = static_cast<int>(std::min_element(cost.begin(), cost.end()) - cost.begin());
    if (cost[best] > kMatchCost) return std::nullopt;
    if (best == 0 || best == 2 * kMaxShiftPx) return best - kMaxShiftPx;
    // Sub-pixel: the parabola through the best shift and its neighbours.
    const double l = cost[best - 1], c = cost[best], r = cost[best + 1];
    const double curvature = l - 2.0 * c + r;
    const double offset = curvature > 0.0 ? std::clamp(0.5 * (l - r) / curvature, -0.5, 0.5) : 0.0;
    return best - kMaxShiftPx + offset;
}

bool ViewMotion::agreed_shift(const Projections& before, const Projections& now, double& shift, double& drift) {
    int n = 0;
    for (int b = 0; b < kBands; ++b) {
        if (!before.tells[b] || !now.tells[b]) continue;
        if (const std::optional<double> s = best_shift(before.profile[b], now.profile[b])) shifts_[n++] = *s;
    }
    shift = drift = 0.0;
    // Still, if enough bands did not move or cannot tell (a plain background round a lone mover
    // shows nothing else moving), drifting by the mean of the still bands' own shifts where it stands
    // clear of their scatter; else moved by the shift with the most bands within kAgreePx of it (the
    // mean of those), if they are enough.
    int count = 0;
    double small_sum = 0.0, small_squares = 0.0;
    for (int i = 0; i < n; ++i)
        if (std::abs(shifts_[i]) < kAgreePx) {
            ++count;
            small_sum += shifts_[i];
            small_squares += shifts_[i] * shifts_[i];
        }
    const int still = kBands - n + count;
    if (kShare * still >= kBands) {
        // Their mean, where it stands clear of their scatter (twice its standard error): a still
        // view's bands scatter round 0, a slow pan's round its drift.
        if (count >= 2) {
            const double mean = small_sum / count;
            const double spread = std::sqrt(std::max(0.0, (small_squares - count * mean * mean) / (count - 1)));
            if (std::abs(mean) * std::sqrt(static_cast<double>(count)) > kDriftClear * spread) drift = mean;
        }
        return true;
    }
    int most = 0;
    for (int i = 0; i < n; ++i) {
        int support = 0;
        double sum = 0.0;
        for (int j = 0; j < n; ++j)
            if (std::abs(shifts_[j] - shifts_[i]) < kAgreePx) {
                ++support;
                sum += shifts_[j];
            }
        if (support > most) {
            most = support;
            shift = sum / support;
        }
    }
    drift = shift;
    return kShare * most >= kBands;
}

RAYS_FRAME_KERNEL
void ViewMotion::take(const FloatImage& smoothed) {
    compared_ = has_previous_;
    if (has_previous_) {
        previous_columns_ = columns_;
        previous_rows_ = rows_;
    }
    constexpr int kBandPx = kFrameSize / kBands;
    for (auto& p : columns_.profile) p.fill(0.0f);
    for (int y = 0; y < kFrameSize; ++y) {
        const float* row = smoothed.row(y);
        Profile& columns = columns_.profile[y / kBandPx];
        for (int x = 0; x < kFrameSize; ++x) columns[x] += row[x];
        for (int b = 0; b < kBands; ++b) {
            float sum = 0.0f;
            for (int x = b * kBandPx; x < (b + 1) * kBandPx; ++x) sum += row[x];
            rows_.profile[b][y] = sum;
        }
    }
    for (int b = 0; b < kBands; ++b) {
        for (float& v : columns_.profile[b]) v /= kBandPx;
        for (float& v : rows_.profile[b]) v /= kBandPx;
        columns_.tells[b] = normalise(columns_.profile[b]);
        rows_.tells[b] = normalise(rows_.profile[b]);
    }
    has_previous_ = true;
    measured_ = false;
}

const ViewShift& ViewMotion::since_previous() {
    if (measured_) return view_;
    view_ = {};
    // Horizontal bands' column sums tell the shift along x, vertical bands' row sums along y.
    if (compared_) {
        const bool x_known = agreed_shift(previous_columns_, columns_, view_.shift.x, view_.drift.x);
        const bool y_known = agreed_shift(previous_rows_, rows_, view_.shift.y, view_.drift.y);
        view_.known = x_known && y_known;
    }
    view_.still = view_.known && view_.shift.x == 0.0 && view_.shift.y == 0.0;
    measured_ = true;
    return view_;
}

const GreyImage& align_previous(const GreyImage& previous, const GreyImage& frame, Point shift, GreyImage& out) {
    if (shift.x == 0.0 && shift.y == 0.0) return previous;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            const double px = x - shift.x, py = y - shift.y;
            const bool off = px < 0.0 || py < 0.0 || px > kFrameSize - 1 || py > kFrameSize - 1;
            out.at(x, y) = off ? frame.at(x, y)
                               : static_cast<std::uint8_t>(std::lround(sample_bilinear(previous, px, py)));
        }
    return out;
}

}  // namespace rays
