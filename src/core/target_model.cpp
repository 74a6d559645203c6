#include "core/target_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

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
    inside_spread = std::sqrt(std::max(0.0f, sq / n - mean * mean));
    rim_contrast = kSeedContrast;
    valid = true;
}

void TargetModel::follow_exposure(float mean) {
    constexpr float kDarkest = 1.0f;  // grey: below this the frame says nothing about exposure
    constexpr float kStep = 0.05f;    // a change of the frame's mean by more than this in one frame is an
                                      // exposure step; slower changes (scene, drift) are left to learning
    const float gain = frame_mean > kDarkest ? mean / frame_mean : 1.0f;
    if (valid && mean > kDarkest && std::abs(gain - 1.0f) > kStep) {
        for (float& m : inside_mean) m *= gain;
        inside_spread *= gain;
        rim_contrast *= gain;
    }
    frame_mean = mean;
}

void TargetModel::learn(const Contour& contour, std::vector<float>& scratch) {
    std::array<float, kBins> pol{}, mean{}, count{};
    int edges = 0;
    float spread = 0;
    for (int j = 0; j < contour.size; ++j) {
        const ContourPoint& c = contour.points[j];
        if (c.no_edge) continue;
        const int b = bin(c.phi);
        pol[b] += c.grad > 0 ? 1.0f : -1.0f;
        mean[b] += c.inside_mean;
        count[b] += 1.0f;
        spread += c.inside_sd;
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
    global_mean /= static_cast<float>(edges);
    global_pol /= static_cast<float>(edges);
    // Bins no ray fell into take the whole contour's values.
    const float rate = valid ? kRate : 1.0f;
    for (int b = 0; b < kBins; ++b) {
        const float p = count[b] > 0 ? pol[b] / count[b] : global_pol;
        const float m = count[b] > 0 ? mean[b] / count[b] : global_mean;
        polarity[b] += rate * (p - polarity[b]);
        inside_mean[b] += rate * (m - inside_mean[b]);
    }
    inside_spread += rate * (spread / static_cast<float>(edges) - inside_spread);
    rim_contrast += rate * (rim - rim_contrast);
    valid = true;
}

}  // namespace rays
