// SPDX-License-Identifier: Apache-2.0
#include "core/fft_columns.hpp"

#include <cmath>
#include <numbers>
#include <utility>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

// One butterfly over `columns` columns: (a, b) ← (a + w·b, a − w·b), w = wr + i·wi. The four rows
// never overlap.
void butterfly(float* __restrict ar, float* __restrict ai, float* __restrict br, float* __restrict bi, float wr,
               float wi, int columns) {
    for (int c = 0; c < columns; ++c) {
        const float tr = wr * br[c] - wi * bi[c], ti = wr * bi[c] + wi * br[c];
        br[c] = ar[c] - tr;
        bi[c] = ai[c] - ti;
        ar[c] += tr;
        ai[c] += ti;
    }
}

// The same with w = 1 (the first butterfly of every group): no products.
void butterfly_unit(float* __restrict ar, float* __restrict ai, float* __restrict br, float* __restrict bi, int columns) {
    for (int c = 0; c < columns; ++c) {
        const float tr = br[c], ti = bi[c];
        br[c] = ar[c] - tr;
        bi[c] = ai[c] - ti;
        ar[c] += tr;
        ai[c] += ti;
    }
}

}  // namespace

FftColumns::FftColumns() {
    for (int k = 0; k < kPoints / 2; ++k) {
        const double a = 2.0 * std::numbers::pi * k / kPoints;
        cos_[k] = static_cast<float>(std::cos(a));
        sin_[k] = static_cast<float>(std::sin(a));
    }
    for (int n = 0; n < kPoints; ++n) {
        int r = 0;
        for (int bit = 1, mirror = kPoints / 2; bit < kPoints; bit <<= 1, mirror >>= 1)
            if (n & bit) r |= mirror;
        reversed_[n] = r;
    }
}

RAYS_FRAME_KERNEL
void FftColumns::run(float* re, float* im, int columns, int stride, Direction direction) const {
    for (int n = 0; n < kPoints; ++n) {  // rows into bit-reversed order
        const int r = reversed_[n];
        if (r <= n) continue;
        for (int c = 0; c < columns; ++c) {
            std::swap(re[n * stride + c], re[r * stride + c]);
            std::swap(im[n * stride + c], im[r * stride + c]);
        }
    }
    const float sign = direction == Direction::Forward ? -1.0f : 1.0f;
    for (int half = 1; half < kPoints; half <<= 1) {
        const int twiddle_step = kPoints / (2 * half);
        for (int start = 0; start < kPoints; start += 2 * half) {
            const int a0 = start * stride, b0 = a0 + half * stride;
            butterfly_unit(re + a0, im + a0, re + b0, im + b0, columns);
            for (int k = 1; k < half; ++k) {
                const int a = (start + k) * stride, b = a + half * stride;
                butterfly(re + a, im + a, re + b, im + b, cos_[k * twiddle_step], sign * sin_[k * twiddle_step], columns);
            }
        }
    }
}

}  // namespace rays
