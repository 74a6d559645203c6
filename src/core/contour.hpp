// SPDX-License-Identifier: Apache-2.0
// The result of one contour extraction: one point per ray, ordered by angle (star-shaped around ref).
#pragma once
#include <vector>

#include "core/image.hpp"
#include "core/tracker_config.hpp"

namespace rays {

struct ContourPoint {
    Point p;                 // image position, processing pixels
    float phi = 0;           // ray angle, rad, 0 = +x, increasing toward +y
    float lambda = 0;        // distance from ref, px
    bool no_edge = false;    // "no edge on this ray": λ interpolated from the neighbours
    float grad = 0;          // dρ/dλ at the chosen edge (0 when no_edge)
    float inside_mean = 0;   // grey mean on the outer two thirds from ref to the edge (0 when no_edge)
    float inside_sd = 0;     // grey spread there
    float outside_mean = -1; // grey mean of a short band just outside the edge (< 0: off the image)
};

struct Contour {
    explicit Contour(const TrackerCapacity& capacity)
        : points(capacity.max_rays),
          crossings(static_cast<std::size_t>(capacity.max_rays) * capacity.max_hypotheses),
          crossing_count(capacity.max_rays),
          max_crossings(capacity.max_hypotheses) {}

    int size = 0;                     // valid entries in points
    std::vector<ContourPoint> points; // capacity max_rays
    // Further accepted edge crossings on ray j (concave parts, §2.4): crossings[j·max_crossings + c].
    std::vector<float> crossings;
    std::vector<int> crossing_count;
    int max_crossings;

    Point ref;          // the reference point m the rays were shot from
    Point centroid;     // centre of the enclosed area
    double area = 0;    // enclosed area, px²
    int levels = 0;     // any-time levels completed (a partly done level counts as not complete)
    bool deadline_hit = false;
    int iterations = 0; // centroid iterations (eq. 11)
    int no_edge_rays = 0;

    float crossing(int ray, int c) const { return crossings[static_cast<std::size_t>(ray) * max_crossings + c]; }
};

// How much the contour looks like the outline of one object: along its rays the inside differs from
// the band just outside by more than the inside varies, and few rays lack an edge. Used to choose
// among start points of a new track.
double contour_objectness(const Contour& contour);

// The mean of the rays' inside grey (rays with an edge only; 0 when none has one).
double mean_inside_grey(const Contour& contour);

// Whether p lies inside the contour polygon (even-odd rule).
bool contour_contains(const Contour& contour, Point p);

// Area and centre of the enclosed area of a closed polygon (shoelace formula).
void polygon_area_centroid(const ContourPoint* pts, int n, double& area, Point& centroid);

}  // namespace rays
