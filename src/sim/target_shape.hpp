// SPDX-License-Identifier: Apache-2.0
// What a simulated target looks like: its outline in degrees on the plane tangent to the sphere at
// its centre (x right, y down), and that outline as one of the inside-predicates of
// scenes/shapes.hpp in "world pixels" — kWorldPxPerDeg of them per degree — centred on (0, 0).
#pragma once
#include <variant>

#include "scenes/shapes.hpp"
#include "sim/paths.hpp"

namespace rays::sim {

inline constexpr double kWorldPxPerDeg = 10.0;

struct DiscShape {
    double diameter_deg = 8;
};

struct EllipseShape {
    double width_deg = 6;
    double height_deg = 8;
};

struct StarShape {
    double outer_diameter_deg = 8;
    double inner_diameter_deg = 4;
    int points = 5;
    double spin_deg_s = 0;  // rotation rate, positive clockwise as seen
};

// A walking human silhouette. Its gait cycle advances by one every 0.8 heights of azimuth walked
// (signed, so walking back plays the gait backward, which the mirror-symmetric figure shows as
// walking the other way).
struct WalkerShape {
    double height_deg = 12;
};

using TargetShape = std::variant<DiscShape, EllipseShape, StarShape, WalkerShape>;
using PlanarShape = std::variant<scenes::Disc, scenes::Ellipse, scenes::Star, scenes::Walker>;

// The outline at time t for a target whose centre is at `where` (the walker's gait and the star's
// spin depend on them).
PlanarShape planar_shape(const TargetShape& shape, double t_s, const PathPoint& where);

// A box around the outline, world px.
scenes::Box outline_box(const PlanarShape& shape);

}  // namespace rays::sim
