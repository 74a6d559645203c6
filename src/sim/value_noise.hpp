// SPDX-License-Identifier: Apache-2.0
// Smooth value noise for the simulated world's textures (the panorama and textured targets):
// random values on an integer lattice, smoothstep-interpolated, deterministic for a seed.
#pragma once
#include <cstdint>

namespace rays::sim {

// One octave in [0, 1] at lattice coordinates (x, y). With period_x > 0 the lattice repeats every
// period_x cells along x, so a texture can wrap round the full circle of azimuth.
double value_noise(double x, double y, std::uint64_t seed, std::int64_t period_x = 0);

// `octaves` octaves of value noise, each at twice the frequency and half the weight of the one
// before, normalised back to [0, 1]. period_x as above, for the first octave.
double fractal_noise(double x, double y, std::uint64_t seed, int octaves, std::int64_t period_x = 0);

}  // namespace rays::sim
