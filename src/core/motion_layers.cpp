// SPDX-License-Identifier: Apache-2.0
#include "core/motion_layers.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr float kForget = 0.1f;       // of the map, forgotten per frame (the evidence of ≈ 10 frames)
constexpr float kFrameNats = 1.0f;    // one frame's evidence at a place is bounded by this
constexpr float kLeastScale = 1.0f;   // grey: the residuals' scale is at least this
constexpr int kLeastFrames = 3;       // frames of evidence before the map is read
constexpr int kInsideRays = 48;       // contour points the inside samples lie toward ...
constexpr float kInsideAt[] = {0.25f, 0.5f, 0.75f};  // ... at these fractions of the way from m
constexpr int kSearchPx = 2;          // the target's shift is searched this far round each guess

static_assert(MotionLayers::kInsideSamples == kInsideRays * static_cast<int>(std::size(kInsideAt)));

// Bilinear between the four values at r0[0], r0[1] and a row `stride` below, at (fx, fy) past the first.
float blend4(const float* r0, int stride, float fx, float fy) {
    const float* r1 = r0 + stride;
    const float top = r0[0] + fx * (r0[1] - r0[0]);
    const float bottom = r1[0] + fx * (r1[1] - r1[0]);
    return top + fy * (bottom - top);
}

int floor_half(int n) { return n >= 0 ? n / 2 : -((1 - n) / 2); }  // ⌊n / 2⌋ for any sign

}  // namespace

bool MotionLayers::valid() const { return frames_ >= kLeastFrames; }

RAYS_FRAME_KERNEL
float MotionLayers::inside_residual(const FloatImage& before, int dx, int dy) const {
    float sum = 0.0f;
    int count = 0;
    for (int k = 0; k < inside_count_; ++k) {
        const Tap& t = taps_[k];
        const int x = t.x0 - dx, y = t.y0 - dy;
        if (x < 0 || y < 0 || x > kFrameSize - 2 || y > kFrameSize - 2) continue;
        sum += std::abs(inside_now_[k] - blend4(before.row(y) + x, kFrameSize, t.fx, t.fy));
        ++count;
    }
    return count > 0 ? sum / static_cast<float>(count) : std::numeric_limits<float>::max();
}

RAYS_FRAME_KERNEL
float MotionLayers::inside_residual(const FloatImage& before, Point shift) const {
    // A tap at x0 + fx moved back by the shift's whole part w and fraction f (0 ≤ f < 1) lies at
    // x0 − w + (fx − f), one pixel further left where fx < f.
    const double wx = std::floor(shift.x), wy = std::floor(shift.y);
    const auto fx_shift = static_cast<float>(shift.x - wx), fy_shift = static_cast<float>(shift.y - wy);
    const int dx = static_cast<int>(wx), dy = static_cast<int>(wy);
    float sum = 0.0f;
    int count = 0;
    for (int k = 0; k < inside_count_; ++k) {
        const Tap& t = taps_[k];
        const bool left = t.fx < fx_shift, up = t.fy < fy_shift;
        const int x = t.x0 - dx - (left ? 1 : 0), y = t.y0 - dy - (up ? 1 : 0);
        const float fx = t.fx - fx_shift + (left ? 1.0f : 0.0f), fy = t.fy - fy_shift + (up ? 1.0f : 0.0f);
        if (x < 0 || y < 0 || x > kFrameSize - 2 || y > kFrameSize - 2) continue;
        sum += std::abs(inside_now_[k] - blend4(before.row(y) + x, kFrameSize, fx, fy));
        ++count;
    }
    return count > 0 ? sum / static_cast<float>(count) : std::numeric_limits<float>::max();
}

Point MotionLayers::match_shift(const FloatImage& now, const FloatImage& before, const Contour& contour, Point moved_by) {
    inside_count_ = 0;
    const int n = contour.size;
    for (int r = 0; r < kInsideRays; ++r) {
        const Point p = contour.points[static_cast<std::size_t>(r * n / kInsideRays)].p;
        for (float f : kInsideAt) {
            Point q{contour.ref.x + f * (p.x - contour.ref.x), contour.ref.y + f * (p.y - contour.ref.y)};
            q = {std::clamp(q.x, 0.0, kFrameSize - 1.001), std::clamp(q.y, 0.0, kFrameSize - 1.001)};
            Tap& t = taps_[inside_count_];
            t.x0 = static_cast<int>(q.x);
            t.y0 = static_cast<int>(q.y);
            t.fx = static_cast<float>(q.x - t.x0);
            t.fy = static_cast<float>(q.y - t.y0);
            inside_now_[inside_count_++] = sample_bilinear(now, q.x, q.y);
        }
    }
    // Whole pixels round the centroid's shift and round the target's last shift (a contour that
    // changed shape moves its centroid further than the target), then halves and quarters round the best.
    const int gx = static_cast<int>(std::lround(moved_by.x)), gy = static_cast<int>(std::lround(moved_by.y));
    const int lx = frames_ > 0 ? static_cast<int>(std::lround(shift_.x)) : gx;
    const int ly = frames_ > 0 ? static_cast<int>(std::lround(shift_.y)) : gy;
    Point best = moved_by;
    float least = inside_residual(before, best);
    auto consider = [&](int x, int y) {
        const float r = inside_residual(before, x, y);
        if (r < least) least = r, best = {static_cast<double>(x), static_cast<double>(y)};
    };
    for (int dy = -kSearchPx; dy <= kSearchPx; ++dy)
        for (int dx = -kSearchPx; dx <= kSearchPx; ++dx) consider(gx + dx, gy + dy);
    for (int dy = -kSearchPx; dy <= kSearchPx; ++dy)
        for (int dx = -kSearchPx; dx <= kSearchPx; ++dx) {
            const int x = lx + dx, y = ly + dy;
            if (std::abs(x - gx) > kSearchPx || std::abs(y - gy) > kSearchPx) consider(x, y);  // not looked at yet
        }
    for (double step : {0.5, 0.25}) {
        const Point centre = best;
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
                if (dx == 0 && dy == 0) continue;
                const Point s{centre.x + dx * step, centre.y + dy * step};
                const float r = inside_residual(before, s);
                if (r < least) least = r, best = s;
            }
    }
    return best;
}

RAYS_FRAME_KERNEL
void MotionLayers::sample_cells(const FloatImage& image, Point shift, CellPlane& out, std::array<bool, kChromaPixels>& off) {
    // Cell (i, j)'s centre 2i + 0.5 moved back by the shift lies in pixel column 2i + ox, at fx
    // beyond it: the same ox and fx for every cell (and likewise for rows). So the cells on the
    // image are a rectangle: columns i_from … i_to of rows whose pixel row is on it.
    const double bx = 0.5 - shift.x, by = 0.5 - shift.y;
    const int ox = static_cast<int>(std::floor(bx)), oy = static_cast<int>(std::floor(by));
    const auto fx = static_cast<float>(bx - ox), fy = static_cast<float>(by - oy);
    // 0 ≤ 2i + ox ≤ kFrameSize − 2
    const int i_from = std::clamp(floor_half(1 - ox), 0, kChromaSize);              // ⌈−ox / 2⌉
    const int i_to = std::clamp(floor_half(kFrameSize - 2 - ox), -1, kChromaSize - 1);
    for (int j = 0; j < kChromaSize; ++j) {
        const int y = 2 * j + oy;
        bool* off_row = off.data() + j * kChromaSize;
        if (y < 0 || y > kFrameSize - 2) {
            std::fill(off_row, off_row + kChromaSize, true);
            continue;
        }
        std::fill(off_row, off_row + kChromaSize, false);
        for (int i = 0; i < i_from; ++i) off_row[i] = true;
        for (int i = i_to + 1; i < kChromaSize; ++i) off_row[i] = true;
        const float* row = image.row(y);
        float* cells = out.data() + j * kChromaSize;
        for (int i = i_from; i <= i_to; ++i) cells[i] = blend4(row + 2 * i + ox, kFrameSize, fx, fy);
    }
}

void MotionLayers::add_moved(Point shift, float keep, CellPlane& out) const {
    // What is at cell i now was shift / 2 cells back: at i + ou, fu beyond it, the same for every cell.
    const double bu = -0.5 * shift.x, bv = -0.5 * shift.y;
    const int ou = static_cast<int>(std::floor(bu)), ov = static_cast<int>(std::floor(bv));
    const auto fu = static_cast<float>(bu - ou), fv = static_cast<float>(bv - ov);
    // The cells whose source lies on the map: 0 ≤ i + ou ≤ kChromaSize − 2, likewise for j.
    const int i_from = std::max(0, -ou), i_to = std::min(kChromaSize - 1, kChromaSize - 2 - ou);
    const int j_from = std::max(0, -ov), j_to = std::min(kChromaSize - 1, kChromaSize - 2 - ov);
    for (int j = j_from; j <= j_to; ++j) {
        const float* source = &map_.log_odds[static_cast<std::size_t>((j + ov) * kChromaSize)];
        float* cells = &out[static_cast<std::size_t>(j * kChromaSize)];
        for (int i = i_from; i <= i_to; ++i) cells[i] += keep * blend4(source + i + ou, kChromaSize, fu, fv);
    }
}

RAYS_FRAME_KERNEL
void MotionLayers::update(const FloatImage& now, const FloatImage& before, const Contour& contour, Point moved_by,
                          Point view) {
    if (contour.size < 3) return;
    shift_ = match_shift(now, before, contour, moved_by);
    // Each place now, and before as each layer moved (a cell's centre: the mean of its 2×2 pixels).
    for (int j = 0; j < kChromaSize; ++j) {
        const float* r0 = now.row(2 * j);
        const float* r1 = r0 + kFrameSize;
        for (int i = 0; i < kChromaSize; ++i)
            here_[static_cast<std::size_t>(j * kChromaSize + i)] = 0.25f * (r0[2 * i] + r0[2 * i + 1] + r1[2 * i] + r1[2 * i + 1]);
    }
    sample_cells(before, shift_, target_, target_off_);
    sample_cells(before, view, view_, view_off_);
    // The residuals' scale is the mean of the smaller one over the frame: the residual of whichever
    // layer a place is on. A place one layer's motion brings from off the image tells nothing.
    double scale_sum = 0.0;
    int scale_count = 0;
    for (std::size_t c = 0; c < kChromaPixels; ++c) {
        const bool seen = !target_off_[c] && !view_off_[c];
        target_[c] = seen ? std::abs(here_[c] - target_[c]) : 0.0f;
        view_[c] = seen ? std::abs(here_[c] - view_[c]) : 0.0f;
        scale_sum += std::min(target_[c], view_[c]);
        scale_count += seen ? 1 : 0;
    }
    const float scale = std::max(kLeastScale, static_cast<float>(scale_sum / std::max(scale_count, 1)));
    // The map moves with the target and forgets a little; each place adds how much better the
    // target's motion explains it than the view's: with Laplacian residuals, the log-likelihood
    // ratio is their difference over the scale.
    next_.fill(0.0f);
    if (frames_ > 0) add_moved(shift_, 1.0f - kForget, next_);
    for (std::size_t c = 0; c < kChromaPixels; ++c) {
        const float evidence = std::clamp((view_[c] - target_[c]) / scale, -kFrameNats, kFrameNats);
        map_.log_odds[c] = std::clamp(next_[c] + evidence, -LikelihoodMap::kMaxLogOdds, LikelihoodMap::kMaxLogOdds);
    }
    ++frames_;
}

void MotionLayers::add_to(LikelihoodMap& map, Point ahead) const {
    add_moved(ahead, 1.0f, map.log_odds);
    for (float& v : map.log_odds) v = std::clamp(v, -LikelihoodMap::kMaxLogOdds, LikelihoodMap::kMaxLogOdds);
}

void MotionLayers::add_background_to(LikelihoodMap& map, Point ahead) {
    moved_.fill(0.0f);
    add_moved(ahead, 1.0f, moved_);
    for (std::size_t c = 0; c < kChromaPixels; ++c)
        map.log_odds[c] = std::clamp(map.log_odds[c] + std::min(moved_[c], 0.0f), -LikelihoodMap::kMaxLogOdds, LikelihoodMap::kMaxLogOdds);
}

}  // namespace rays
