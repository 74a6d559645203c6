// SPDX-License-Identifier: Apache-2.0
#include "core/background_model.hpp"

#include <algorithm>
#include <cmath>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr float kRate = 0.05f;                // weight of the newest frame in the background (≈ 20 frames)
constexpr int kInterleave = 4;                // rows learned per frame: one in this many, in turn
constexpr int kReadyFrames = 10;              // frames learned before the foreground is used
constexpr double kTargetMarginPx = 3.0;       // the box round the target left unlearned grows by this
constexpr float kNoiseFloor = 1.0f;           // grey: the least noise assumed
constexpr float kFromNoise = 2.5f;            // |difference| below this × noise is background (0) …
constexpr float kFullNoise = 6.0f;            // … above this × noise (and kFullGrey) foreground (1)
constexpr float kFullGrey = 8.0f;             // grey
constexpr double kMaxForegroundShare = 0.35;  // of the frame: more foreground than this says nothing
constexpr float kAbsorbFrames = 15.0f;        // foreground unchanged this long is background, target or not
constexpr float kStillNoise = 4.0f;           // unchanged: within this × noise of the row as last learned
constexpr float kStillGrey = 3.0f;            // (and at least this)
constexpr int kSampleStride = 8;              // rows between those the noise and the foreground's area are read from

}  // namespace

bool BackgroundModel::ready() const { return frames_ >= kReadyFrames; }

const FloatImage* BackgroundModel::foreground() const {
    return ready() && foreground_area_ <= kMaxForegroundShare * kFramePixels ? &foreground_ : nullptr;
}

RAYS_FRAME_KERNEL
void BackgroundModel::rate(const FloatImage& smoothed) {
    if (!ready()) return;
    const auto noise = static_cast<float>(noise_);
    const float from = kFromNoise * noise;
    const float gain = 1.0f / (std::max(kFullNoise * noise, kFullGrey) - from);
    for (int i = 0; i < kFramePixels; ++i)
        foreground_.px[i] = std::clamp((std::abs(smoothed.px[i] - background_.px[i]) - from) * gain, 0.0f, 1.0f);
    double area = 0.0;  // from every kSampleStride-th row: enough to tell a frame unlike the background
    for (int y = 0; y < kFrameSize; y += kSampleStride)
        for (int x = 0; x < kFrameSize; ++x) area += foreground_.at(x, y);
    foreground_area_ = area * kSampleStride;
}

RAYS_FRAME_KERNEL
void BackgroundModel::learn(const FloatImage& smoothed, const Contour* target) {
    if (frames_ == 0) {
        background_ = smoothed;
        last_ = smoothed;
        unchanged_.px.fill(0.0f);
        noise_ = kNoiseFloor;
        frames_ = 1;
        return;
    }
    // The target's box (with a margin for its blurred rim) keeps the background it hides.
    int x0 = kFrameSize, x1 = -1, y0 = kFrameSize, y1 = -1;
    if (target != nullptr && target->size > 0) {
        double lx = kFrameSize, hx = -1, ly = kFrameSize, hy = -1;
        for (int i = 0; i < target->size; ++i) {
            const Point p = target->points[i].p;
            lx = std::min(lx, p.x), hx = std::max(hx, p.x), ly = std::min(ly, p.y), hy = std::max(hy, p.y);
        }
        x0 = std::max(0, static_cast<int>(std::floor(lx - kTargetMarginPx)));
        x1 = std::min(kFrameSize - 1, static_cast<int>(std::ceil(hx + kTargetMarginPx)));
        y0 = std::max(0, static_cast<int>(std::floor(ly - kTargetMarginPx)));
        y1 = std::min(kFrameSize - 1, static_cast<int>(std::ceil(hy + kTargetMarginPx)));
    }
    // Until ready, every pixel is learned (a running mean); then only those that look like the
    // background, so a mover outside the box (before a track, or beside a wrong one) leaves no trail.
    // Once ready, each frame learns every kInterleave-th row, in turn, at kInterleave × the rate:
    // the same background for a fraction of the time.
    const bool warming = !ready();
    const float rate = warming ? 1.0f / static_cast<float>(frames_ + 1) : kRate * kInterleave;
    const int row_step = warming ? 1 : kInterleave, first_row = warming ? 0 : frames_ % kInterleave;
    const float from = kFromNoise * static_cast<float>(noise_);
    const float clip = kFullNoise * static_cast<float>(noise_);
    const float still = std::max(kStillNoise * static_cast<float>(noise_), kStillGrey);
    // The noise: the mean difference over the background outside the box, from every
    // kSampleStride-th row, a mover's pixels counting as no more than strong noise.
    double sum = 0.0;
    int count = 0;
    for (int y = 0; y < kFrameSize; y += kSampleStride)
        for (int x = 0; x < kFrameSize; ++x) {
            if (y >= y0 && y <= y1 && x >= x0 && x <= x1) continue;
            sum += std::min(std::abs(smoothed.at(x, y) - background_.at(x, y)), clip);
            ++count;
        }
    // Branch-free, so that it vectorises (with -fno-trapping-math, see CMakeLists.txt), as does
    // rate()'s loop. As 0/1 masks: foreground that stands still becomes background at once; the
    // rest is learned where it looks like the background (while warming: everywhere) outside the
    // target's box.
    const float warm = warming ? 1.0f : 0.0f, absorb_after = kAbsorbFrames / static_cast<float>(row_step);
    for (int y = first_row; y < kFrameSize; y += row_step) {
        const float* s = smoothed.row(y);
        float* l = last_.row(y);
        float* b = background_.row(y);
        float* u = unchanged_.row(y);
        const bool rows_hidden = y >= y0 && y <= y1;
        const auto lo = static_cast<float>(rows_hidden ? x0 : kFrameSize), hi = static_cast<float>(rows_hidden ? x1 : kFrameSize);
        for (int x = 0; x < kFrameSize; ++x) {
            const float d = s[x] - b[x];
            const float foreground = std::abs(d) >= from ? 1.0f : 0.0f;
            const float same = std::abs(s[x] - l[x]) < still ? 1.0f : 0.0f;
            const float n = (u[x] + 1.0f) * foreground * same;
            const float absorb = n >= absorb_after ? 1.0f : 0.0f;
            const auto xf = static_cast<float>(x);
            const float shown = (xf < lo ? 1.0f : 0.0f) + (xf > hi ? 1.0f : 0.0f);
            const float learn = rate * shown * (warm + (1.0f - warm) * (1.0f - foreground));
            b[x] += (absorb + (1.0f - absorb) * learn) * d;
            u[x] = (1.0f - absorb) * n;
            l[x] = s[x];
        }
    }
    if (count > 0) noise_ = std::max<double>(kNoiseFloor, sum / count);
    ++frames_;
}

}  // namespace rays
