// SPDX-License-Identifier: Apache-2.0
#include "sim/target_shape.hpp"

#include <cmath>
#include <numbers>

#include "common/angles.hpp"

namespace rays::sim {
namespace {

constexpr double kGaitCycleHeights = 0.8;  // azimuth walked per gait cycle, in the walker's heights

struct ToPlanar {
    double t_s;
    const PathPoint& where;

    PlanarShape operator()(const DiscShape& s) const { return scenes::Disc{0, 0, s.diameter_deg * kWorldPxPerDeg / 2}; }
    PlanarShape operator()(const EllipseShape& s) const {
        // Semi-axis a along the angle π/2 (down), b across it.
        return scenes::Ellipse{0, 0, s.height_deg * kWorldPxPerDeg / 2, s.width_deg * kWorldPxPerDeg / 2,
                               std::numbers::pi / 2};
    }
    PlanarShape operator()(const StarShape& s) const {
        return scenes::Star{0, 0, s.outer_diameter_deg * kWorldPxPerDeg / 2, s.inner_diameter_deg * kWorldPxPerDeg / 2,
                            s.points, s.spin_deg_s * t_s * kRadPerDeg};
    }
    PlanarShape operator()(const WalkerShape& s) const {
        const double walked_deg = where.position.azimuth * kDegPerRad;
        const double phase = 2.0 * std::numbers::pi * walked_deg / (kGaitCycleHeights * s.height_deg);
        return scenes::Walker{0, 0, s.height_deg * kWorldPxPerDeg, phase};
    }
};

}  // namespace

PlanarShape planar_shape(const TargetShape& shape, double t_s, const PathPoint& where) {
    return std::visit(ToPlanar{t_s, where}, shape);
}

scenes::Box outline_box(const PlanarShape& shape) {
    return std::visit([](const auto& s) { return s.box(); }, shape);
}

}  // namespace rays::sim
