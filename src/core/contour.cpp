#include "core/contour.hpp"

#include <cmath>

namespace rays {

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
