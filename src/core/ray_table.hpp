// SPDX-License-Identifier: Apache-2.0
// Precomputed ray directions and the coarse-to-fine order in which rays are shot (Fig. 6, §2.3).
#pragma once
#include <vector>

namespace rays {

class RayTable {
public:
    explicit RayTable(int max_rays);

    // Sets the final ray count (Δφ = 2π / count, count ≤ capacity). No allocation.
    void set_count(int count);

    int capacity() const { return capacity_; }
    int count() const { return count_; }
    double angle(int i) const { return angle_[i]; }
    double cos_at(int i) const { return cos_[i]; }
    double sin_at(int i) const { return sin_[i]; }

    // Ray indices in the order they are shot: level 0 holds rays 0 and π (Fig. 6 INIT), every
    // further level doubles the count. For counts that are not powers of two the order follows the
    // van der Corput sequence over the final angles, which keeps every prefix spread evenly.
    int order(int k) const { return order_[k]; }
    int levels() const { return levels_; }
    // Number of rays shot once `level` (0-based) is complete.
    int level_end(int level) const { return level_end_[level]; }

private:
    int capacity_;
    int count_ = 0;
    int levels_ = 0;
    std::vector<double> angle_, cos_, sin_;
    std::vector<int> order_;
    std::vector<int> level_end_;
    std::vector<unsigned char> placed_;
};

}  // namespace rays
