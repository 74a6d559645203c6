// SPDX-License-Identifier: Apache-2.0
// Shapes as inside-predicates with a bounding box, for anti-aliased drawing (see Canvas::paint).
// Coordinates in px, x right, y down, pixel centres at integers; angles in rad.
#pragma once

namespace rays::scenes {

struct Box {
    double x0, y0, x1, y1;
    bool inside(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    Box box() const { return *this; }
};

struct Disc {
    double cx, cy, r;
    bool inside(double x, double y) const;
    Box box() const;
};

struct Ellipse {
    double cx, cy, a, b, angle = 0;  // semi-axes a (along angle) and b
    bool inside(double x, double y) const;
    Box box() const;
};

// A thick line segment with round ends: the points within half_width of the segment a–b.
struct Capsule {
    double ax, ay, bx, by, half_width;
    bool inside(double x, double y) const;
    Box box() const;
};

// An n-pointed star with rounded points (concave): the radius swings between inner and outer.
struct Star {
    double cx, cy, outer, inner;
    int points = 5;
    double rotation = 0;
    bool inside(double x, double y) const;
    Box box() const;
};

// A walking human silhouette `height` px tall with (cx, cy) at the middle of the figure: head,
// torso, two legs swinging with `phase` (one gait cycle per 2π) and arms swinging against them.
struct Walker {
    double cx, cy, height, phase;
    bool inside(double x, double y) const;
    Box box() const;
};

}  // namespace rays::scenes
