// SPDX-License-Identifier: Apache-2.0
#include "snake/snake_contour.hpp"

#include <cmath>
#include <numbers>

#include "snake/image_gradient.hpp"

namespace rays::snake {
namespace {

double angle_round(Point centre, const SnakePoint& p) {
    const double a = std::atan2(p.y - centre.y, p.x - centre.x);
    return a < 0 ? a + 2.0 * std::numbers::pi : a;
}

}  // namespace

TrackerCapacity snake_contour_capacity(const TrackerCapacity& capacity) {
    TrackerCapacity c = capacity;
    c.max_rays = capacity.max_snake_points;
    c.max_hypotheses = 1;  // a snake has no further crossings per point
    return c;
}

void write_snake_contour(const GreedySnake& snake, const FloatImage& smoothed, const SnakeRun& run, Contour& out) {
    const int n = snake.size();
    double signed_area2 = 0.0;  // > 0 when the ring runs the way angles grow (x right, y down)
    for (int i = 0; i < n; ++i) {
        const SnakePoint& p = snake.point(i);
        const SnakePoint& q = snake.point((i + 1) % n);
        signed_area2 += p.x * q.y - q.x * p.y;
        out.points[i] = {};
        out.points[i].p = {static_cast<double>(p.x), static_cast<double>(p.y)};
    }
    polygon_area_centroid(out.points.data(), n, out.area, out.centroid);

    int first = 0;
    for (int i = 1; i < n; ++i)
        if (angle_round(out.centroid, snake.point(i)) < angle_round(out.centroid, snake.point(first))) first = i;
    const int direction = signed_area2 >= 0 ? 1 : -1;
    const double edge_floor = snake.tunables().edge_floor;
    out.no_edge_rays = 0;
    for (int k = 0; k < n; ++k) {
        const SnakePoint& s = snake.point(((first + direction * k) % n + n) % n);
        ContourPoint& c = out.points[k];
        c = {};
        c.p = {static_cast<double>(s.x), static_cast<double>(s.y)};
        const double phi = angle_round(out.centroid, s);
        c.phi = static_cast<float>(phi);
        c.lambda = static_cast<float>(std::hypot(c.p.x - out.centroid.x, c.p.y - out.centroid.y));
        c.no_edge = snake.gradient_magnitude().at(s.x, s.y) < edge_floor;
        if (c.no_edge) {
            ++out.no_edge_rays;
        } else {
            const Point g = gradient_at(smoothed, s.x, s.y);
            c.grad = static_cast<float>(g.x * std::cos(phi) + g.y * std::sin(phi));
        }
        out.crossing_count[k] = 0;
    }
    out.size = n;
    out.ref = out.centroid;
    out.iterations = run.iterations;
    out.deadline_hit = run.deadline_hit;
    out.levels = run.deadline_hit ? 0 : 1;
}

}  // namespace rays::snake
