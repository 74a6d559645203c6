// SPDX-License-Identifier: Apache-2.0
#include "scenes/shapes.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays::scenes {

bool Disc::inside(double x, double y) const { return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r; }

Box Disc::box() const { return {cx - r - 1, cy - r - 1, cx + r + 1, cy + r + 1}; }

bool Ellipse::inside(double x, double y) const {
    const double c = std::cos(angle), s = std::sin(angle);
    const double u = (x - cx) * c + (y - cy) * s, v = -(x - cx) * s + (y - cy) * c;
    return (u * u) / (a * a) + (v * v) / (b * b) <= 1.0;
}

Box Ellipse::box() const {
    const double r = std::max(a, b) + 1;
    return {cx - r, cy - r, cx + r, cy + r};
}

bool Capsule::inside(double x, double y) const {
    const double vx = bx - ax, vy = by - ay, length2 = vx * vx + vy * vy;
    const double t = length2 > 0 ? std::clamp(((x - ax) * vx + (y - ay) * vy) / length2, 0.0, 1.0) : 0.0;
    const double dx = x - ax - t * vx, dy = y - ay - t * vy;
    return dx * dx + dy * dy <= half_width * half_width;
}

Box Capsule::box() const {
    const double w = half_width + 1;
    return {std::min(ax, bx) - w, std::min(ay, by) - w, std::max(ax, bx) + w, std::max(ay, by) + w};
}

bool Star::inside(double x, double y) const {
    const double d = std::hypot(x - cx, y - cy);
    if (d > outer) return false;
    const double phi = std::atan2(y - cy, x - cx);
    const double w = 0.5 + 0.5 * std::cos(points * (phi - rotation));
    return d <= inner + (outer - inner) * w * w;
}

Box Star::box() const { return {cx - outer - 1, cy - outer - 1, cx + outer + 1, cy + outer + 1}; }

// Proportions in units of the height, from the middle of the figure: the head's top at −0.485 h,
// the feet's soles at +0.545 h, at most 0.215 h to either side.
bool Walker::inside(double x, double y) const {
    const double h = height;
    if (Disc{cx, cy - 0.40 * h, 0.085 * h}.inside(x, y)) return true;                                  // head
    if (Ellipse{cx, cy - 0.13 * h, 0.20 * h, 0.10 * h, std::numbers::pi / 2}.inside(x, y)) return true;  // torso
    const double hip_y = cy + 0.05 * h, foot_y = cy + 0.5 * h, swing = 0.17 * h * std::sin(phase);
    const double leg = 0.045 * h;
    if (Capsule{cx - 0.03 * h, hip_y, cx - swing, foot_y, leg}.inside(x, y)) return true;
    if (Capsule{cx + 0.03 * h, hip_y, cx + swing, foot_y, leg}.inside(x, y)) return true;
    const double arm = 0.03 * h, shoulder_y = cy - 0.28 * h, shoulder_x = 0.08 * h;  // arms swing against the legs
    if (Capsule{cx - shoulder_x, shoulder_y, cx - shoulder_x + 0.6 * swing, cy, arm}.inside(x, y)) return true;
    return Capsule{cx + shoulder_x, shoulder_y, cx + shoulder_x - 0.6 * swing, cy, arm}.inside(x, y);
}

Box Walker::box() const {
    const double h = height;
    return {cx - 0.3 * h, cy - 0.5 * h - 1, cx + 0.3 * h, cy + 0.55 * h + 1};
}

}  // namespace rays::scenes
