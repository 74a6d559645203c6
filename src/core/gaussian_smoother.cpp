#include "core/gaussian_smoother.hpp"

#include <algorithm>
#include <cmath>

namespace rays {

void GaussianSmoother::set_sigma(double sigma_px) {
    sigma_ = std::clamp(sigma_px, 0.0, kMaxRadius / 3.0);
    radius_ = sigma_ > 0.0 ? std::min(kMaxRadius, static_cast<int>(std::ceil(3.0 * sigma_))) : 0;
    double sum = 0.0;
    for (int k = -radius_; k <= radius_; ++k) {
        const double w = radius_ == 0 ? 1.0 : std::exp(-0.5 * k * k / (sigma_ * sigma_));
        kernel_[static_cast<std::size_t>(k + radius_)] = static_cast<float>(w);
        sum += w;
    }
    for (int k = 0; k <= 2 * radius_; ++k) kernel_[static_cast<std::size_t>(k)] /= static_cast<float>(sum);
}

void GaussianSmoother::smooth(const GreyImage& in, FloatImage& out) {
    constexpr int n = kFrameSize;
    const int r = radius_;
    const float* kern = kernel_.data() + r;  // kern[-r..r]
    // Horizontal pass over a row padded with replicated edge pixels, tap by tap so it vectorises.
    std::array<float, kFrameSize + 2 * kMaxRadius> padded;
    for (int y = 0; y < n; ++y) {
        const std::uint8_t* src = in.row(y);
        float* __restrict dst = horizontal_.row(y);
        for (int x = -r; x < n + r; ++x) padded[static_cast<std::size_t>(x + r)] = static_cast<float>(src[std::clamp(x, 0, n - 1)]);
        for (int x = 0; x < n; ++x) dst[x] = 0.0f;
        for (int k = -r; k <= r; ++k) {
            const float w = kern[k];
            const float* __restrict p = padded.data() + r + k;
            for (int x = 0; x < n; ++x) dst[x] += w * p[x];
        }
    }
    // Vertical pass: whole rows at a time.
    for (int y = 0; y < n; ++y) {
        float* __restrict dst = out.row(y);
        for (int x = 0; x < n; ++x) dst[x] = 0.0f;
        for (int k = -r; k <= r; ++k) {
            const float* __restrict src = horizontal_.row(std::clamp(y + k, 0, n - 1));
            const float w = kern[k];
            for (int x = 0; x < n; ++x) dst[x] += w * src[x];
        }
    }
}

}  // namespace rays
