// SPDX-License-Identifier: Apache-2.0
#include "core/contour.hpp"

#include <cmath>

namespace rays {

double contour_objectness(const Contour& contour) {
    constexpr double kSpreadFloor = 4.0;  // grey
    double sum = 0.0;
    int edges = 0;
    for (int i = 0; i < contour.size; ++i) {
        const ContourPoint& c = contour.points[i];
        if (c.no_edge || c.outside_mean < 0) continue;
        sum += std::abs(c.inside_mean - c.outside_mean) / (c.inside_sd + kSpreadFloor);
        ++edges;
    }
    return contour.size > 0 ? sum / contour.size : 0.0;  // rays without an edge count as 0
}

double mean_inside_grey(const Contour& contour) {
    double sum = 0.0;
    int edges = 0;
    for (int i = 0; i < contour.size; ++i) {
        if (contour.points[i].no_edge) continue;
        sum += contour.points[i].inside_mean;
        ++edges;
    }
    return edges > 0 ? sum / edges : 0.0;
}

bool contour_contains(const Contour& contour, Point p) {
    bool inside = false;
    for (int i = 0, j = contour.size - 1; i < contour.size; j = i++) {
        const Point& a = contour.points[i].p;
        const Point& b = contour.points[j].p;
        if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    }
    return inside;
}

void polygon_area_centroid(const ContourPoint* pts, int n, double& area, Point& centroid) {
    double a2 = 0.0, cx = 0.0, cy = 0.0;
    for (int i = 0; i < n; ++i) {
        const Point& p = pts[i].p;
        const Point& q = pts[(i + 1) % n].p;
        const double cross = p.x * q.y - q.x * p.y;
        a2 += cross;
        cx += (p.x + q.x) * cross;
        cy += (p.y + q.y) * cross;
    }
    area = 0.5 * std::abs(a2);
    if (std::abs(a2) < 1e-9) {  // degenerate: the mean of the points
        cx = cy = 0.0;
        for (int i = 0; i < n; ++i) {
            cx += pts[i].p.x;
            cy += pts[i].p.y;
        }
        centroid = n > 0 ? Point{cx / n, cy / n} : Point{};
        return;
    }
    centroid = {cx / (3.0 * a2), cy / (3.0 * a2)};
}

}  // namespace rays
