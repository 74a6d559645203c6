// SPDX-License-Identifier: Apache-2.0
// Four floats, or four ints, in one vector register: GCC's vector extension (SSE on x86-64, NEON on
// arm64; clang builds it too). The frame path's innermost loops (the rays' samples, the ring's
// states) run four at a time in them, each lane doing the scalar arithmetic in its order, so the
// numbers are the scalar code's to the bit.
#pragma once
#include <bit>
#include <cstring>

namespace rays {

inline constexpr int kLanes = 4;
using Lanes = float __attribute__((vector_size(kLanes * sizeof(float))));
using LaneIndex = int __attribute__((vector_size(kLanes * sizeof(int))));

inline constexpr LaneIndex kLaneOffsets = {0, 1, 2, 3};  // lane l of a group starting at j is j + l

// Room for n values in whole groups of lanes: n rounded up to a multiple of kLanes.
inline constexpr int whole_lanes(int n) { return (n + kLanes - 1) / kLanes * kLanes; }

// kLanes floats from p on (no alignment needed).
inline Lanes load_lanes(const float* p) {
    Lanes v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

inline void store_lanes(float* p, Lanes v) { std::memcpy(p, &v, sizeof v); }

// |v| lane by lane (the sign bit cleared, as std::abs does).
inline Lanes abs_lanes(Lanes v) { return std::bit_cast<Lanes>(std::bit_cast<LaneIndex>(v) & 0x7fffffff); }

}  // namespace rays
