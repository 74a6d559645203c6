// SPDX-License-Identifier: Apache-2.0
// Blocky random textures for scenes drawn by the tests: a hash of a block's integer coordinates
// gives its value, so a texture moves with its offset and is the same on every run.
#pragma once
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

}  // namespace rays::test
