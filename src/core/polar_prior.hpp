// SPDX-License-Identifier: Apache-2.0
// The previous frame's contour, moved by the predicted motion, seen from a new reference point:
// λ_prior(φ) for every ray, the anchor of the temporal term and of the "no edge" state. A box start's
// prior instead is the ellipse inscribed in the box, which also bounds where the rays search.
#pragma once
#include <optional>
#include <vector>

#include "core/box.hpp"
#include "core/image.hpp"
#include "core/ray_table.hpp"

namespace rays {

class PolarPrior {
public:
    explicit PolarPrior(int max_rays)
        : points_(max_rays), angle_(max_rays), lambda_(max_rays), from_(max_rays), to_(max_rays),
          point_open_(max_rays), open_(max_rays) {}

    // A polygon ordered by angle round a point inside it (copied; no allocation). `open` (optional)
    // marks the points where that contour found no edge.
    void set_polygon(const Point* pts, int n, const unsigned char* open = nullptr);
    void set_circle(double radius_px);
    // A box start (core/box.hpp): the ellipse inscribed in the box, and rays that search only from
    // part of the way to the ellipse to a little beyond the box's border, since the box is the
    // target's extent. Until the next set_polygon or set_circle.
    void set_box(const Box& box);

    // Fills λ_prior for every ray of the table as seen from m, clamped to [lo, hi], and the span of λ
    // each ray searches.
    void resample(const RayTable& table, Point m, double lo, double hi);
    float lambda(int ray) const { return lambda_[ray]; }
    // The span of λ the ray searches for an edge: [lo, hi], or within a box start's box.
    float search_from(int ray) const { return from_[ray]; }
    float search_to(int ray) const { return to_[ray]; }
    // The ray crosses the polygon next to a point where it had no edge.
    bool open(int ray) const { return open_[ray] != 0; }
    float mean_radius() const { return mean_radius_; }

private:
    void resample_lambda(const RayTable& table, Point m, double lo, double hi);

    std::vector<Point> points_;
    std::vector<double> angle_;
    std::vector<float> lambda_, from_, to_;
    std::vector<unsigned char> point_open_, open_;
    int n_ = 0;
    double circle_ = 10.0;
    std::optional<Box> bound_;  // a box start's box, grown by the margin
    float mean_radius_ = 10.0f;
};

}  // namespace rays
