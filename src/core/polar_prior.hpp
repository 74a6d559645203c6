// The previous frame's contour, moved by the predicted motion, seen from a new reference point:
// λ_prior(φ) for every ray, the anchor of the temporal term and of the "no edge" state.
#pragma once
#include <vector>

#include "core/image.hpp"
#include "core/ray_table.hpp"

namespace rays {

class PolarPrior {
public:
    explicit PolarPrior(int max_rays) : points_(max_rays), angle_(max_rays), lambda_(max_rays) {}

    // A polygon ordered by angle round a point inside it (copied; no allocation).
    void set_polygon(const Point* pts, int n);
    void set_circle(double radius_px);

    // Fills λ_prior for every ray of the table as seen from m, clamped to [lo, hi].
    void resample(const RayTable& table, Point m, double lo, double hi);
    float lambda(int ray) const { return lambda_[ray]; }
    float mean_radius() const { return mean_radius_; }

private:
    std::vector<Point> points_;
    std::vector<double> angle_;
    std::vector<float> lambda_;
    int n_ = 0;
    double circle_ = 10.0;
    float mean_radius_ = 10.0f;
};

}  // namespace rays
