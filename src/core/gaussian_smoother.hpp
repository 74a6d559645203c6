// SPDX-License-Identifier: Apache-2.0
// Gaussian pre-smoothing G_σ of the paper's eq. 4, separable, into a preallocated float image.
#pragma once
#include <array>

#include "core/image.hpp"

namespace rays {

class GaussianSmoother {
public:
    static constexpr int kMaxRadius = 8;  // σ up to kMaxRadius / 3 px

    // σ ≤ 0 copies the image unchanged. σ is clamped to kMaxRadius / 3.
    void set_sigma(double sigma_px);
    double sigma() const { return sigma_; }

    // Smooths `in` into `out`; borders replicate the edge pixel. No allocation.
    void smooth(const GreyImage& in, FloatImage& out);

private:
    double sigma_ = 0.0;
    int radius_ = 0;
    std::array<float, kMaxRadius + 1> kernel_{};  // w_0 … w_radius of the symmetric kernel
    FloatImage horizontal_;  // the horizontal pass, kept to avoid a per-frame buffer
};

}  // namespace rays
