// SPDX-License-Identifier: Apache-2.0
// Drawing for the scenes: a float canvas with the target's coverage, textures, clutter,
// anti-aliased shapes, lighting, blur and noise, all deterministic.
#pragma once
#include <cstdint>

#include "scenes/scene.hpp"
#include "scenes/shapes.hpp"

namespace rays::scenes {

// splitmix64: a small deterministic generator, seeded per scene and frame.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    double uniform();   // [0, 1)
    double gaussian();  // N(0, 1)

private:
    std::uint64_t state_;
};

class Canvas {
public:
    // Backgrounds; each also clears the target.
    void fill(double grey);
    void gradient(double grey_at_centre, double per_px_x, double per_px_y);
    // Smooth value-noise texture of the given mean and amplitude (grey levels), cell size px.
    void texture(double mean, double amplitude, double cell_px, std::uint64_t seed);

    // Background detail, hidden by a target painted later.
    void rect(double x0, double y0, double x1, double y1, double grey);
    void line(double x0, double y0, double x1, double y1, double width_px, double grey);
    // `count` rectangles and straight lines of random size, place and grey in [grey_lo, grey_hi].
    void clutter(int count, double grey_lo, double grey_hi, std::uint64_t seed);

    // Paints a shape with 4×4 supersampled coverage; it becomes (part of) the target when `target`,
    // otherwise it hides the target where it covers it (an occluder).
    template <class Shape>
    void paint(const Shape& shape, double grey, bool target);
    // An occluding bar in front of everything: the target's mask excludes it.
    void occlude(double x0, double y0, double x1, double y1, double grey);

    // Lighting over everything drawn so far: grey × factor where nx·x + ny·y > offset (a shadow
    // border, softened over one pixel).
    void multiply_half_plane(double nx, double ny, double offset, double factor);
    void gaussian_blur(double sigma_px);  // optics: blurs the image, not the truth
    void noise(double sigma, Random& random);

    void finish(SceneFrame& out) const;  // quantises, and takes mask and truth from the coverage

private:
    Plane<float> grey_{};
    Plane<float> coverage_{};  // target coverage, 0…1
};

}  // namespace rays::scenes
