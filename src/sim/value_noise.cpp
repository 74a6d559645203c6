// SPDX-License-Identifier: Apache-2.0
#include "sim/value_noise.hpp"

#include <cmath>

namespace rays::sim {
namespace {

// splitmix64's finaliser over the lattice point and seed: a uniform value in [0, 1).
double lattice_value(std::int64_t x, std::int64_t y, std::uint64_t seed) {
    std::uint64_t z = seed ^ (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^
                      (static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

double smoothstep(double t) { return t * t * (3 - 2 * t); }

std::int64_t wrap(std::int64_t i, std::int64_t period) {
    if (period <= 0) return i;
    const std::int64_t r = i % period;
    return r < 0 ? r + period : r;
}

}  // namespace

double value_noise(double x, double y, std::uint64_t seed, std::int64_t period_x) {
    const double fx = std::floor(x), fy = std::floor(y);
    const auto ix = static_cast<std::int64_t>(fx), iy = static_cast<std::int64_t>(fy);
    const double tx = smoothstep(x - fx), ty = smoothstep(y - fy);
    const std::int64_t x0 = wrap(ix, period_x), x1 = wrap(ix + 1, period_x);
    const double a = lattice_value(x0, iy, seed), b = lattice_value(x1, iy, seed);
    const double c = lattice_value(x0, iy + 1, seed), d = lattice_value(x1, iy + 1, seed);
    return (a + (b - a) * tx) * (1 - ty) + (c + (d - c) * tx) * ty;
}

double fractal_noise(double x, double y, std::uint64_t seed, int octaves, std::int64_t period_x) {
    double sum = 0, weight_sum = 0, weight = 1, scale = 1;
    for (int octave = 0; octave < octaves; ++octave) {
        const auto seed_of_octave = seed + static_cast<std::uint64_t>(octave) * 0x632BE59BD9B4E019ull;
        sum += weight * value_noise(x * scale, y * scale, seed_of_octave, period_x * (std::int64_t{1} << octave));
        weight_sum += weight;
        weight *= 0.5;
        scale *= 2;
    }
    return sum / weight_sum;
}

}  // namespace rays::sim
