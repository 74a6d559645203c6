// SPDX-License-Identifier: Apache-2.0
#include "core/ray_table.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {
namespace {

// Bit-reversed fraction of k: 0, 1/2, 1/4, 3/4, 1/8, ... (van der Corput, base 2).
double van_der_corput(unsigned k) {
    double v = 0.0, bit = 0.5;
    for (; k != 0; k >>= 1, bit *= 0.5)
        if (k & 1u) v += bit;
    return v;
}

}  // namespace

RayTable::RayTable(int max_rays)
    : capacity_(std::max(2, max_rays)),
      angle_(capacity_),
      cos_(capacity_),
      sin_(capacity_),
      order_(capacity_),
      level_end_(40),
      placed_(capacity_) {
    set_count(capacity_);
}

void RayTable::set_count(int count) {
    count_ = std::clamp(count, 2, capacity_);
    for (int i = 0; i < count_; ++i) {
        angle_[i] = 2.0 * std::numbers::pi * i / count_;
        cos_[i] = std::cos(angle_[i]);
        sin_[i] = std::sin(angle_[i]);
    }
    std::fill(placed_.begin(), placed_.begin() + count_, 0);
    int shot = 0;
    levels_ = 0;
    // Sequence positions 0..2^(L+1)-1 make up levels 0..L; positions with spacing ≤ 1/count cover
    // every index, so the loop ends after at most 4·count positions.
    for (unsigned k = 0; shot < count_; ++k) {
        const int i = static_cast<int>(std::lround(van_der_corput(k) * count_)) % count_;
        if (!placed_[i]) {
            placed_[i] = 1;
            order_[shot++] = i;
        }
        const unsigned next = k + 1;
        if (next >= 2 && (next & (next - 1)) == 0) {  // a power of two: a level ends
            if (levels_ == 0 || level_end_[levels_ - 1] != shot) level_end_[levels_++] = shot;
        }
    }
    if (levels_ == 0 || level_end_[levels_ - 1] != count_) level_end_[levels_++] = count_;
}

}  // namespace rays
