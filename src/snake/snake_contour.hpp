// SPDX-License-Identifier: Apache-2.0
// The greedy snake as the trackers' common Contour: points in the order of their angle round the
// centroid (the snake's own ring, started at the smallest angle and walked the way angles grow),
// with φ, λ, the edge at each point, ref = centroid, and area and centroid of the polygon.
#pragma once
#include "core/contour.hpp"
#include "snake/greedy_snake.hpp"

namespace rays::snake {

// The capacity of a Contour that holds a snake of up to capacity.max_snake_points points.
TrackerCapacity snake_contour_capacity(const TrackerCapacity& capacity);

// Writes `snake` into `out` (sized by snake_contour_capacity). A point on |∇I| below
// tunables().edge_floor is marked no_edge; grad is dI/dλ there, from the smoothed frame.
// levels is 1 unless the deadline cut the passes short (0).
void write_snake_contour(const GreedySnake& snake, const FloatImage& smoothed, const SnakeRun& run, Contour& out);

}  // namespace rays::snake
