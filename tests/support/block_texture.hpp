// SPDX-License-Identifier: Apache-2.0
// Blocky random textures for scenes drawn by the tests: a hash of a block's integer coordinates
// gives its value, so a texture moves with its offset and is the same on every run.
#pragma once
#include <cmath>
#include <cstdint>

namespace rays::test {

inline std::uint32_t block_hash(int x, int y, std::uint32_t seed) {
    std::uint32_t h = static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u ^ seed * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    return h ^ (h >> 15);
}

// a / b rounded toward −∞: the block a coordinate lies in, negative coordinates included.
inline int floor_div(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

// A world of `block`-px blocks of random grey from `low` to `low + span`, interpolated between block
// centres so that it moves smoothly by fractions of a pixel.
inline double smooth_blocks(double x, double y, std::uint32_t seed, double block = 6.0, int low = 40, int span = 160) {
    const double u = x / block, v = y / block;
    const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
    const double fx = u - i, fy = v - j;
    auto at = [&](int a, int b) { return static_cast<double>(low + static_cast<int>(block_hash(a, b, seed) % static_cast<std::uint32_t>(span + 1))); };
    const double top = at(i, j) + fx * (at(i + 1, j) - at(i, j));
    const double bottom = at(i, j + 1) + fx * (at(i + 1, j + 1) - at(i, j + 1));
    return top + fy * (bottom - top);
}

}  // namespace rays::test
