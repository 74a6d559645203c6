// SPDX-License-Identifier: Apache-2.0
#include "core/gaussian_smoother.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr int n = kFrameSize;

// The separable passes for a kernel of radius R known at compile time: each output pixel is
// w0·p(x) + Σ_k w_k (p(x−k) + p(x+k)), summed in a register, which the compiler vectorises.
template <int R>
RAYS_FRAME_KERNEL
void smooth_radius(const float* kern, const GreyImage& in, FloatImage& horizontal, FloatImage& out) {
    // Horizontal pass over a row padded with replicated edge pixels.
    std::array<float, n + 2 * GaussianSmoother::kMaxRadius> padded;
    for (int y = 0; y < n; ++y) {
        const std::uint8_t* src = in.row(y);
        for (int x = 0; x < n; ++x) padded[static_cast<std::size_t>(x + R)] = src[x];
        for (int k = 0; k < R; ++k) {
            padded[static_cast<std::size_t>(k)] = src[0];
            padded[static_cast<std::size_t>(n + R + k)] = src[n - 1];
        }
        const float* p = padded.data() + R;
        float* __restrict dst = horizontal.row(y);
        for (int x = 0; x < n; ++x) {
            float s = kern[0] * p[x];
            for (int k = 1; k <= R; ++k) s += kern[k] * (p[x - k] + p[x + k]);
            dst[x] = s;
        }
    }
    // Vertical pass: whole rows at a time, rows beyond the border replicated.
    for (int y = 0; y < n; ++y) {
        std::array<const float*, 2 * R + 1> rows;
        for (int k = -R; k <= R; ++k) rows[static_cast<std::size_t>(k + R)] = horizontal.row(std::clamp(y + k, 0, n - 1));
        float* __restrict dst = out.row(y);
        for (int x = 0; x < n; ++x) {
            float s = kern[0] * rows[R][x];
            for (int k = 1; k <= R; ++k) s += kern[k] * (rows[static_cast<std::size_t>(R - k)][x] + rows[static_cast<std::size_t>(R + k)][x]);
            dst[x] = s;
        }
    }
}

using SmoothFn = void (*)(const float*, const GreyImage&, FloatImage&, FloatImage&);

template <std::size_t... R>
constexpr std::array<SmoothFn, sizeof...(R)> smooth_table(std::index_sequence<R...>) {
    return {&smooth_radius<static_cast<int>(R)>...};
}

constexpr auto kSmoothByRadius = smooth_table(std::make_index_sequence<GaussianSmoother::kMaxRadius + 1>{});

}  // namespace

void GaussianSmoother::set_sigma(double sigma_px) {
    sigma_ = std::clamp(sigma_px, 0.0, kMaxRadius / 3.0);
    radius_ = sigma_ > 0.0 ? std::min(kMaxRadius, static_cast<int>(std::ceil(3.0 * sigma_))) : 0;
    std::array<double, kMaxRadius + 1> w{};
    double sum = 0.0;
    for (int k = 0; k <= radius_; ++k) {
        w[static_cast<std::size_t>(k)] = radius_ == 0 ? 1.0 : std::exp(-0.5 * k * k / (sigma_ * sigma_));
        sum += (k == 0 ? 1.0 : 2.0) * w[static_cast<std::size_t>(k)];  // w_k stands for taps −k and +k
    }
    for (int k = 0; k <= radius_; ++k) kernel_[static_cast<std::size_t>(k)] = static_cast<float>(w[static_cast<std::size_t>(k)] / sum);
}

void GaussianSmoother::smooth(const GreyImage& in, FloatImage& out) {
    kSmoothByRadius[static_cast<std::size_t>(radius_)](kernel_.data(), in, horizontal_, out);
}

}  // namespace rays
