// SPDX-License-Identifier: Apache-2.0
// The target's running area while nothing hid part of it: a contour with at least `share` of it shows
// the whole target and moves it (by `rate`); a smaller one (a partly hidden target) leaves it.
#pragma once

namespace rays {

class WholeArea {
public:
    explicit WholeArea(double share = 0.8, double rate = 0.1) : share_(share), rate_(rate) {}

    void reset() { area_ = 0.0; }
    bool shows_whole(double area) const { return area_ <= 0.0 || area >= share_ * area_; }
    void update(double area) {
        if (area_ <= 0.0) area_ = area;
        else if (shows_whole(area)) area_ += rate_ * (area - area_);
    }
    double area() const { return area_; }
    double share() const { return share_; }
    double rate() const { return rate_; }

private:
    double share_, rate_;
    double area_ = 0.0;
};

}  // namespace rays
