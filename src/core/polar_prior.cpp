// SPDX-License-Identifier: Apache-2.0
#include "core/polar_prior.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

// A box start's rays search from kBoxNearShare of the way to the box's ellipse (an edge deep inside the
// box, a mark on the target, is not its rim) to kBoxMarginPx or kBoxMarginShare of the box's width
// (height), whichever is more, beyond its border (a rim on the border, or a box drawn a little tight,
// is still seen).
constexpr int kEllipsePoints = 64;  // vertices of a box start's ellipse
constexpr double kBoxNearShare = 0.4;
constexpr double kBoxMarginPx = 4.0;
constexpr double kBoxMarginShare = 0.15;

// How far the ray from m in direction (c, s) runs inside the box (0 from outside it).
double reach_in(const Box& box, Point m, double c, double s) {
    double reach = 1e9;
    if (c > 1e-9) reach = std::min(reach, (box.x + box.w - m.x) / c);
    if (c < -1e-9) reach = std::min(reach, (box.x - m.x) / c);
    if (s > 1e-9) reach = std::min(reach, (box.y + box.h - m.y) / s);
    if (s < -1e-9) reach = std::min(reach, (box.y - m.y) / s);
    return std::max(reach, 0.0);
}

// A stand-in for the direction's angle from 0 to 2π, rising with it from 0 to 4 (the "diamond
// angle"): orders directions as atan2 does, for a division instead of atan2's hundred cycles.
double pseudo_angle(double dx, double dy) {
    if (dy >= 0.0) {
        if (dx >= 0.0) return dx + dy > 0.0 ? dy / (dx + dy) : 0.0;
        return 1.0 - dx / (dy - dx);
    }
    return dx < 0.0 ? 2.0 - dy / (-dx - dy) : 3.0 + dx / (dx - dy);
}

}  // namespace

void PolarPrior::set_polygon(const Point* pts, int n, const unsigned char* open) {
    bound_.reset();
    n_ = std::min(n, static_cast<int>(points_.size()));
    std::copy(pts, pts + n_, points_.begin());
    if (open) std::copy(open, open + n_, point_open_.begin());
    else std::fill(point_open_.begin(), point_open_.begin() + n_, 0);
}

void PolarPrior::set_circle(double radius_px) {
    bound_.reset();
    n_ = 0;
    circle_ = radius_px;
}

void PolarPrior::set_box(const Box& box) {
    const Point c = box.centre();
    const double rx = 0.5 * box.w, ry = 0.5 * box.h;
    n_ = std::min(kEllipsePoints, static_cast<int>(points_.size()));
    for (int k = 0; k < n_; ++k) {  // by angle round the centre, as set_polygon wants
        const double t = 2.0 * std::numbers::pi * k / n_;
        points_[k] = {c.x + rx * std::cos(t), c.y + ry * std::sin(t)};
    }
    std::fill(point_open_.begin(), point_open_.begin() + n_, 0);
    circle_ = std::max(std::min(rx, ry), 1.0);  // too few rays for a polygon: a circle inside the box
    // The box's own extent is [x − ½, x + w − ½] (pixel centres at integers), grown by the margin.
    const double mx = std::max(kBoxMarginPx, kBoxMarginShare * box.w);
    const double my = std::max(kBoxMarginPx, kBoxMarginShare * box.h);
    bound_ = Box{box.x - 0.5 - mx, box.y - 0.5 - my, box.w + 2.0 * mx, box.h + 2.0 * my};
}

void PolarPrior::resample(const RayTable& table, Point m, double lo, double hi) {
    resample_lambda(table, m, lo, hi);
    const int rays = table.count();
    if (!bound_) {
        std::fill(from_.begin(), from_.begin() + rays, static_cast<float>(lo));
        std::fill(to_.begin(), to_.begin() + rays, static_cast<float>(hi));
        return;
    }
    for (int i = 0; i < rays; ++i) {
        from_[i] = static_cast<float>(std::clamp(kBoxNearShare * lambda_[i], lo, hi));
        to_[i] = static_cast<float>(std::clamp(reach_in(*bound_, m, table.cos_at(i), table.sin_at(i)), lo, hi));
    }
}

RAYS_FRAME_KERNEL
void PolarPrior::resample_lambda(const RayTable& table, Point m, double lo, double hi) {
    const int rays = table.count();
    double sum = 0.0;
    if (n_ < 3) {
        const float r = static_cast<float>(std::clamp(circle_, lo, hi));
        std::fill(lambda_.begin(), lambda_.begin() + rays, r);
        std::fill(open_.begin(), open_.begin() + rays, 0);
        mean_radius_ = r;
        return;
    }
    constexpr double turn = 4.0;  // a whole turn in pseudo_angle()
    // Vertex angles round m, unwrapped from the vertex with the smallest angle so that they rise.
    int first = 0;
    for (int k = 0; k < n_; ++k) {
        angle_[k] = pseudo_angle(points_[k].x - m.x, points_[k].y - m.y);
        if (angle_[k] < angle_[first]) first = k;
    }
    int k = 0;  // current edge: vertex (first + k) to (first + k + 1)
    auto vertex = [&](int j) {  // (first + j) mod n_ for 0 ≤ j ≤ n_ + 1, without a division
        const int v = first + j;
        return v < n_ ? v : v - n_ < n_ ? v - n_ : v - 2 * n_;
    };
    auto unwrapped = [&](int j) { return angle_[vertex(j)] + (j >= n_ ? turn : 0.0); };
    for (int i = 0; i < rays; ++i) {
        const double ux = table.cos_at(i), uy = table.sin_at(i);
        const double phi = pseudo_angle(ux, uy);
        while (k < n_ && unwrapped(k + 1) <= phi) ++k;
        // Edge from vertex k to k+1 (wrapping: before the first vertex the edge ends at it).
        const int va = vertex(k == 0 && phi < angle_[first] ? n_ - 1 : k);
        const int vb = vertex(k == 0 && phi < angle_[first] ? 0 : k + 1);
        const Point a = points_[va], b = points_[vb];
        open_[i] = point_open_[va] | point_open_[vb];
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
