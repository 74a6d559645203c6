// Target shapes as inside-predicates with a bounding box, for anti-aliased drawing.
#pragma once
#include "core/image.hpp"

namespace rays::scenes {

struct Box {
    double x0, y0, x1, y1;
    bool inside(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
    Box box() const { return *this; }
};

struct Ellipse {
    double cx, cy, a, b, angle = 0;  // semi-axes a (along angle) and b, px
    bool inside(double x, double y) const;
    Box box() const;
};

// A five-(or n-)pointed star with rounded points: r(φ) between inner and outer radius (concave).
struct Star {
    double cx, cy, outer, inner;
    int points = 5;
    double rotation = 0;
    bool inside(double x, double y) const;
    Box box() const;
};

// A walking human silhouette: head, torso, two legs swinging with `phase`, `height` px tall,
// (cx, cy) at the middle of the figure.
struct Walker {
    double cx, cy, height, phase;
    bool inside(double x, double y) const;
    Box box() const;
};

}  // namespace rays::scenes
