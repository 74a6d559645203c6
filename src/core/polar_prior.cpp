#include "core/polar_prior.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rays {

void PolarPrior::set_polygon(const Point* pts, int n, const unsigned char* open) {
    n_ = std::min(n, static_cast<int>(points_.size()));
    std::copy(pts, pts + n_, points_.begin());
    if (open) std::copy(open, open + n_, point_open_.begin());
    else std::fill(point_open_.begin(), point_open_.begin() + n_, 0);
}

void PolarPrior::set_circle(double radius_px) {
    n_ = 0;
    circle_ = radius_px;
}

void PolarPrior::resample(const RayTable& table, Point m, double lo, double hi) {
    const int rays = table.count();
    double sum = 0.0;
    if (n_ < 3) {
        const float r = static_cast<float>(std::clamp(circle_, lo, hi));
        std::fill(lambda_.begin(), lambda_.begin() + rays, r);
        std::fill(open_.begin(), open_.begin() + rays, 0);
        mean_radius_ = r;
        return;
    }
    constexpr double two_pi = 2.0 * std::numbers::pi;
    // Vertex angles round m, unwrapped from the vertex with the smallest angle so that they rise.
    int first = 0;
    for (int k = 0; k < n_; ++k) {
        double a = std::atan2(points_[k].y - m.y, points_[k].x - m.x);
        angle_[k] = a < 0 ? a + two_pi : a;
        if (angle_[k] < angle_[first]) first = k;
    }
    int k = 0;  // current edge: vertex (first + k) to (first + k + 1)
    auto vertex = [&](int j) { return (first + j) % n_; };
    auto unwrapped = [&](int j) { return angle_[vertex(j)] + (j >= n_ ? two_pi : 0.0); };
    for (int i = 0; i < rays; ++i) {
        const double phi = table.angle(i);
        while (k < n_ && unwrapped(k + 1) <= phi) ++k;
        // Edge from vertex k to k+1 (wrapping: before the first vertex the edge ends at it).
        const int va = vertex(k == 0 && phi < angle_[first] ? n_ - 1 : k);
        const int vb = vertex(k == 0 && phi < angle_[first] ? 0 : k + 1);
        const Point a = points_[va], b = points_[vb];
        open_[i] = point_open_[va] | point_open_[vb];
        const double ux = table.cos_at(i), uy = table.sin_at(i);
        const double ex = b.x - a.x, ey = b.y - a.y;
        const double denom = ux * ey - uy * ex;
        double lam;
        if (std::abs(denom) > 1e-9) {
            lam = ((a.x - m.x) * ey - (a.y - m.y) * ex) / denom;  // ray m + λu meets segment a→b
        } else {
            lam = std::hypot(a.x - m.x, a.y - m.y);
        }
        if (!(lam > 0)) lam = std::hypot(a.x - m.x, a.y - m.y);
        lambda_[i] = static_cast<float>(std::clamp(lam, lo, hi));
        sum += lambda_[i];
    }
    mean_radius_ = static_cast<float>(sum / rays);
}

}  // namespace rays
