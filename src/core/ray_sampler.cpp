// SPDX-License-Identifier: Apache-2.0
#include "core/ray_sampler.hpp"

#include <cstring>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

using Pair = float __attribute__((vector_size(2 * sizeof(float))));
static_assert(kLanes == 4, "the reads below name four lanes");

Lanes clamp_lanes(Lanes v, float lo, float hi) { return v < lo ? lo : (hi < v ? hi : v); }  // std::clamp's order

LaneIndex clamp_lanes(LaneIndex v, int lo, int hi) { return v < lo ? lo : (hi < v ? hi : v); }

// The pixel at p and its right-hand neighbour, in one load.
Pair pair_at(const float* p) {
    Pair v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

// Bilinear in a plane `width` wide between the pixels at `index` and their right, lower and
// lower-right neighbours, at fractions (fx, fy): Plane's and LikelihoodMap's arithmetic, lane by lane.
[[gnu::always_inline]] inline Lanes bilinear(const float* plane, int width, LaneIndex index, Lanes fx, Lanes fy) {
    int at[kLanes];
    std::memcpy(at, &index, sizeof at);
    const float* p0 = plane + at[0];
    const float* p1 = plane + at[1];
    const float* p2 = plane + at[2];
    const float* p3 = plane + at[3];
    // Each row's two neighbours (left, right) of lanes 0 and 1, then of lanes 2 and 3, split into
    // the left ones and the right ones.
    const Lanes t01 = __builtin_shufflevector(pair_at(p0), pair_at(p1), 0, 1, 2, 3);
    const Lanes t23 = __builtin_shufflevector(pair_at(p2), pair_at(p3), 0, 1, 2, 3);
    const Lanes b01 = __builtin_shufflevector(pair_at(p0 + width), pair_at(p1 + width), 0, 1, 2, 3);
    const Lanes b23 = __builtin_shufflevector(pair_at(p2 + width), pair_at(p3 + width), 0, 1, 2, 3);
    const Lanes a = __builtin_shufflevector(t01, t23, 0, 2, 4, 6), b = __builtin_shufflevector(t01, t23, 1, 3, 5, 7);
    const Lanes c = __builtin_shufflevector(b01, b23, 0, 2, 4, 6), d = __builtin_shufflevector(b01, b23, 1, 3, 5, 7);
    const Lanes top = a + fx * (b - a);
    const Lanes bottom = c + fx * (d - c);
    return top + fy * (bottom - top);
}

}  // namespace

RAYS_FRAME_KERNEL
void sample_ray(const FloatImage& image, const LikelihoodMap* likelihood, float x_first, float y_first, float dx,
                float dy, int n, float* grey, float* log_odds) {
    constexpr int kCells = LikelihoodMap::kSize;
    float x = x_first, y = y_first;
    for (int j = 0; j < n; j += kLanes) {
        float xs[kLanes], ys[kLanes];
        for (int l = 0; l < kLanes; ++l, x += dx, y += dy) {
            xs[l] = x;
            ys[l] = y;
        }
        const Lanes px = load_lanes(xs), py = load_lanes(ys);
        // The grey: the pixel at or left of / above the sample, clamped so that its right and lower
        // neighbours exist (a sample on the far border reads them with weight 1).
        const LaneIndex x0 = clamp_lanes(__builtin_convertvector(px, LaneIndex), 0, kFrameSize - 2);
        const LaneIndex y0 = clamp_lanes(__builtin_convertvector(py, LaneIndex), 0, kFrameSize - 2);
        const Lanes fx = px - __builtin_convertvector(x0, Lanes), fy = py - __builtin_convertvector(y0, Lanes);
        const Lanes v = bilinear(image.px.data(), kFrameSize, y0 * kFrameSize + x0, fx, fy);
        store_lanes(grey + j, v);
        if (likelihood == nullptr) continue;
        // The log-odds, between cell centres (cell i at pixel 2i + 0.5), clamped at the border.
        const Lanes u = clamp_lanes((px - 0.5f) * 0.5f, 0.0f, kCells - 1.0f);
        const Lanes w = clamp_lanes((py - 0.5f) * 0.5f, 0.0f, kCells - 1.0f);
        const LaneIndex ci = __builtin_convertvector(u, LaneIndex), cj = __builtin_convertvector(w, LaneIndex);
        const LaneIndex i = ci < kCells - 2 ? ci : kCells - 2, k = cj < kCells - 2 ? cj : kCells - 2;
        const Lanes lo = bilinear(likelihood->log_odds.data(), kCells, k * kCells + i, u - __builtin_convertvector(i, Lanes),
                                  w - __builtin_convertvector(k, Lanes));
        store_lanes(log_odds + j, lo);
    }
}

}  // namespace rays
