// SPDX-License-Identifier: Apache-2.0
#include "core/attention.hpp"

#include <cmath>

namespace rays {

const char* Attention::check(const Contour& contour, Point predicted, const AttentionTunables& limits) {
    const Point previous = current_.centroid;
    current_.area = contour.area;
    current_.centroid = contour.centroid;
    current_.speed_px = has_previous_ ? std::hypot(contour.centroid.x - previous.x, contour.centroid.y - previous.y) : 0.0;
    current_.no_edge_fraction = contour.size > 0 ? static_cast<double>(contour.no_edge_rays) / contour.size : 1.0;

    const char* reason = nullptr;
    if (current_.area < limits.min_area_px)
        reason = "contour area below attention.min_area_px";
    else if (current_.area > limits.max_area_fraction * kFramePixels)
        reason = "contour area above attention.max_area_fraction";
    else if (current_.no_edge_fraction > limits.max_none_fraction)
        reason = "too many rays without an edge";
    else if (has_previous_ && std::abs(current_.area - area_) > limits.max_area_change * area_ &&
             std::abs(current_.area - whole_area_.area()) > limits.max_area_change * whole_area_.area())
        reason = "contour area changed too fast";
    else if (has_previous_ && std::hypot(contour.centroid.x - predicted.x, contour.centroid.y - predicted.y) > limits.max_jump_px)
        reason = "centroid jumped away from its prediction";
    if (reason) return reason;
    area_ = has_previous_ ? 0.7 * area_ + 0.3 * current_.area : current_.area;
    whole_area_.update(current_.area);
    has_previous_ = true;
    return nullptr;
}

}  // namespace rays
