// SPDX-License-Identifier: Apache-2.0
#include "core/target_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/ray_hypotheses.hpp"

namespace rays {
namespace {

constexpr float kRate = 0.3f;  // weight of the newest contour in the running model

}  // namespace

int TargetModel::bin(float phi) {
    const float turns = phi / (2.0f * std::numbers::pi_v<float>);
    const int b = static_cast<int>(std::floor((turns - std::floor(turns)) * kBins));
    return std::clamp(b, 0, kBins - 1);
}

void TargetModel::seed(const FloatImage& image, Point m) {
    constexpr int kHalf = 2;
    constexpr float kSeedContrast = 12.0f;  // grey/px, as before a rim is learned
    const int cx = std::clamp(static_cast<int>(std::lround(m.x)), kHalf, kFrameSize - 1 - kHalf);
    const int cy = std::clamp(static_cast<int>(std::lround(m.y)), kHalf, kFrameSize - 1 - kHalf);
    float sum = 0, sq = 0;
    for (int y = cy - kHalf; y <= cy + kHalf; ++y)
        for (int x = cx - kHalf; x <= cx + kHalf; ++x) {
            sum += image.at(x, y);
            sq += image.at(x, y) * image.at(x, y);
        }
    constexpr float n = (2 * kHalf + 1) * (2 * kHalf + 1);
    const float mean = sum / n;
    polarity.fill(0.0f);
    inside_mean.fill(mean);
    outside_mean.fill(-1.0f);
    inside_spread = std::sqrt(std::max(0.0f, sq / n - mean * mean));
    rim_contrast = kSeedContrast;
    valid = true;
}

void TargetModel::seed_inside(const FloatImage& image, const Box& box) {
    constexpr float kInner = 0.7f;  // of the semi-axes: the part of the ellipse that is surely the target
    const Point c = box.centre();
    const double rx = kInner * 0.5 * box.w, ry = kInner * 0.5 * box.h;
    std::array<float, kBins> sums{}, counts{};
    float sum = 0, sq = 0;
    int n = 0;
    const int x0 = std::max(0, static_cast<int>(std::ceil(c.x - rx))), x1 = std::min(kFrameSize - 1, static_cast<int>(c.x + rx));
    const int y0 = std::max(0, static_cast<int>(std::ceil(c.y - ry))), y1 = std::min(kFrameSize - 1, static_cast<int>(c.y + ry));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double u = (x - c.x) / rx, v = (y - c.y) / ry;
            if (u * u + v * v > 1.0) continue;
            const float g = image.at(x, y);
            const int b = bin(static_cast<float>(std::atan2(y - c.y, x - c.x)));
            sums[b] += g;
            counts[b] += 1.0f;
            sum += g;
            sq += g * g;
            ++n;
        }
    seed(image, c);  // polarity, outside and contrast as any start's; the patch at the centre if the box is tiny
    if (n < 9) return;
    const float mean = sum / static_cast<float>(n);
    for (int b = 0; b < kBins; ++b) inside_mean[b] = counts[b] > 0 ? sums[b] / counts[b] : mean;
    inside_spread = std::sqrt(std::max(0.0f, sq / static_cast<float>(n) - mean * mean));
}

void TargetModel::follow_exposure(float mean) {
    constexpr float kDarkest = 1.0f;  // grey: below this the frame says nothing about exposure
    constexpr float kStep = 0.05f;    // a change of the frame's mean by more than this in one frame is an
                                      // exposure step; slower changes (scene, drift) are left to learning
    const float gain = frame_mean > kDarkest ? mean / frame_mean : 1.0f;
    if (valid && mean > kDarkest && std::abs(gain - 1.0f) > kStep) {
        for (float& m : inside_mean) m *= gain;
        for (float& m : outside_mean) m = m < 0 ? m : m * gain;
        inside_spread *= gain;
        rim_contrast *= gain;
    }
    frame_mean = mean;
}

void TargetModel::learn(const Contour& contour, std::vector<float>& scratch) {
    std::array<float, kBins> pol{}, edges_in{}, mean{}, weight{}, out{}, outs{};
    int edges = 0;
    float spread = 0, weights = 0;
    for (int j = 0; j < contour.size; ++j) {
        const ContourPoint& c = contour.points[j];
        if (c.no_edge) continue;
        const int b = bin(c.phi);
        pol[b] += c.grad > 0 ? 1.0f : -1.0f;
        edges_in[b] += 1.0f;
        // The inside looks are learned from the rays that saw the inside clear of the rim.
        const float w = inside_reliability(c.lambda);
        mean[b] += w * c.inside_mean;
        if (c.outside_mean >= 0) {
            out[b] += c.outside_mean;
            outs[b] += 1.0f;
        }
        weight[b] += w;
        spread += w * c.inside_sd;
        weights += w;
        scratch[edges++] = std::abs(c.grad);
    }
    if (edges < 3) return;
    std::nth_element(scratch.begin(), scratch.begin() + edges / 2, scratch.begin() + edges);
    const float rim = scratch[edges / 2];
    float global_mean = 0, global_pol = 0;
    for (int b = 0; b < kBins; ++b) {
        global_mean += mean[b];
        global_pol += pol[b];
    }
    global_pol /= static_cast<float>(edges);
    constexpr float kLeastWeight = 0.5f;  // less than this says nothing of the inside: looks kept as they were
    const bool looks = weights >= kLeastWeight;
    global_mean = looks ? global_mean / weights : 0.0f;
    // Bins no ray fell into take the whole contour's values.
    const float rate = valid ? kRate : 1.0f;
    for (int b = 0; b < kBins; ++b) {
        const float p = edges_in[b] > 0 ? pol[b] / edges_in[b] : global_pol;
        polarity[b] += rate * (p - polarity[b]);
        // The band outside only where a ray saw it: the background differs round the target.
        if (outs[b] > 0) {
            const float o = out[b] / outs[b];
            outside_mean[b] = outside_mean[b] < 0 ? o : outside_mean[b] + rate * (o - outside_mean[b]);
        } else if (!valid) {
            outside_mean[b] = -1.0f;
        }
        if (!looks) continue;
        const float m = weight[b] > 0.1f ? mean[b] / weight[b] : global_mean;
        inside_mean[b] += rate * (m - inside_mean[b]);
    }
    if (looks) inside_spread += rate * (spread / weights - inside_spread);
    rim_contrast += rate * (rim - rim_contrast);
    valid = true;
}

}  // namespace rays
