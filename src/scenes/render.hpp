// Drawing helpers for the scenes: a float canvas with the target mask, textures, anti-aliased
// shapes, noise and blur, all deterministic.
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
    // Smooth value-noise texture of the given mean and amplitude (grey levels), cell size px.
    void texture(double mean, double amplitude, double cell_px, std::uint64_t seed);
    void fill(double grey);
    void rect(double x0, double y0, double x1, double y1, double grey);  // background detail
    // Paints a shape with 4×4 supersampled coverage; marks it as the target when `target`.
    template <class Shape>
    void paint(const Shape& shape, double grey, bool target);
    void multiply_half_plane(double nx, double ny, double offset, double factor);  // where nx·x+ny·y > offset
    void occlude(double x0, double y0, double x1, double y1, double grey);  // hides the target there
    void noise(double sigma, Random& random);
    void blur3();
    void finish(SceneFrame& out) const;  // quantises and computes the truth from the mask

private:
    Plane<float> grey_{};
    Plane<float> coverage_{};  // target coverage, 0…1
};

}  // namespace rays::scenes
