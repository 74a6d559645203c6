// SPDX-License-Identifier: Apache-2.0
// Eq. 6 along one ray: ρ_m(φ, λ) = f(x_m + λ cos φ, y_m + λ sin φ), bilinear, at n samples a step
// apart — the smoothed grey and, with a colour model, its log-odds (LikelihoodMap::at) — four samples
// at a time in vector lanes (lanes.hpp). Each lane does the scalar reads' arithmetic in their order,
// so every value is the one a scalar bilinear read gives, to the bit (tests/core/test_ray_sampler.cpp).
#pragma once
#include "core/appearance_model.hpp"
#include "core/image.hpp"
#include "core/lanes.hpp"

namespace rays {

// Samples j = 0 … n−1 at (x_j, y_j), x_0 = x_first and x_{j+1} = x_j + dx (added one by one, as a
// scalar loop would), likewise y. Every sample must lie on the image, [0, kFrameSize − 1]². Writes
// grey[j] and, with a likelihood, log_odds[j]; both arrays hold n rounded up to kLanes (the
// lanes past n are written too, from reads clamped to the image).
void sample_ray(const FloatImage& image, const LikelihoodMap* likelihood, float x_first, float y_first, float dx,
                float dy, int n, float* grey, float* log_odds);

}  // namespace rays
