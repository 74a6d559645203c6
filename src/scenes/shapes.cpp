#include "scenes/shapes.hpp"

#include <algorithm>
#include <cmath>

namespace rays::scenes {
namespace {

// Distance from p to the segment a–b.
double segment_distance(double px, double py, double ax, double ay, double bx, double by) {
    const double vx = bx - ax, vy = by - ay;
    const double t = std::clamp(((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy), 0.0, 1.0);
    return std::hypot(px - ax - t * vx, py - ay - t * vy);
}

}  // namespace

bool Ellipse::inside(double x, double y) const {
    const double c = std::cos(angle), s = std::sin(angle);
    const double u = (x - cx) * c + (y - cy) * s, v = -(x - cx) * s + (y - cy) * c;
    return (u * u) / (a * a) + (v * v) / (b * b) <= 1.0;
}

Box Ellipse::box() const {
    const double r = std::max(a, b) + 1;
    return {cx - r, cy - r, cx + r, cy + r};
}

bool Star::inside(double x, double y) const {
    const double d = std::hypot(x - cx, y - cy);
    if (d > outer) return false;
    const double phi = std::atan2(y - cy, x - cx);
    const double w = 0.5 + 0.5 * std::cos(points * (phi - rotation));
    return d <= inner + (outer - inner) * w * w;
}

Box Star::box() const { return {cx - outer - 1, cy - outer - 1, cx + outer + 1, cy + outer + 1}; }

bool Walker::inside(double x, double y) const {
    const double h = height;
    if (std::hypot(x - cx, y - (cy - 0.40 * h)) <= 0.085 * h) return true;  // head
    if (Ellipse{cx, cy - 0.13 * h, 0.20 * h, 0.10 * h, 1.5707963}.inside(x, y)) return true;  // torso
    const double hip_y = cy + 0.05 * h, foot_y = cy + 0.5 * h, swing = 0.17 * h * std::sin(phase);
    const double leg = 0.045 * h;
    if (segment_distance(x, y, cx - 0.03 * h, hip_y, cx - swing, foot_y) <= leg) return true;
    if (segment_distance(x, y, cx + 0.03 * h, hip_y, cx + swing, foot_y) <= leg) return true;
    const double arm = 0.03 * h, shoulder_y = cy - 0.28 * h;  // arms swing against the legs
    if (segment_distance(x, y, cx - 0.08 * h, shoulder_y, cx - 0.08 * h + 0.6 * swing, cy) <= arm) return true;
    return segment_distance(x, y, cx + 0.08 * h, shoulder_y, cx + 0.08 * h - 0.6 * swing, cy) <= arm;
}

Box Walker::box() const {
    const double h = height;
    return {cx - 0.3 * h, cy - 0.5 * h - 1, cx + 0.3 * h, cy + 0.55 * h + 1};
}

}  // namespace rays::scenes
