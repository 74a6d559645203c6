// SPDX-License-Identifier: Apache-2.0
#include "scenes/paths.hpp"

#include <cmath>

namespace rays::scenes {

Point Loop::at(double frame) const {
    const double angle = start + rate * frame;
    const double u = a * std::cos(angle), v = b * std::sin(angle);
    const double c = std::cos(tilt), s = std::sin(tilt);
    return {cx + u * c - v * s, cy + u * s + v * c};
}

double Loop::heading(double frame) const {
    const double angle = start + rate * frame;
    const double du = -a * std::sin(angle) * rate, dv = b * std::cos(angle) * rate;
    const double c = std::cos(tilt), s = std::sin(tilt);
    return std::atan2(du * s + dv * c, du * c - dv * s);
}

double bounce(double lo, double hi, double distance) {
    const double span = hi - lo, d = std::fmod(distance, 2 * span);
    return d < span ? lo + d : hi - (d - span);
}

double ramp_distance(int t) {
    double d = 0;
    for (int i = 0; i < t; ++i) d += i < 170 ? 2.0 + 6.0 * i / 170.0 : i < 230 ? 8.0 : 8.0 + 8.0 * (i - 230) / 169.0;
    return d;
}

}  // namespace rays::scenes
