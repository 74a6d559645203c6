// SPDX-License-Identifier: Apache-2.0
#include "scenes/render.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace rays::scenes {
namespace {

double hash01(std::int64_t x, std::int64_t y, std::uint64_t seed) {
    Random r(seed ^ (static_cast<std::uint64_t>(x) * 0x9E3779B97F4A7C15ull) ^ (static_cast<std::uint64_t>(y) * 0xC2B2AE3D27D4EB4Full));
    return r.uniform();
}

double smooth(double t) { return t * t * (3 - 2 * t); }

// One pass of a normalised 1-D kernel along rows (dx = 1) or columns (dx = 0), edges clamped.
void convolve(const Plane<float>& in, Plane<float>& out, const std::vector<float>& kernel, bool along_x) {
    const int radius = static_cast<int>(kernel.size() / 2);
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            float sum = 0;
            for (int k = -radius; k <= radius; ++k) {
                const int sx = along_x ? std::clamp(x + k, 0, kFrameSize - 1) : x;
                const int sy = along_x ? y : std::clamp(y + k, 0, kFrameSize - 1);
                sum += kernel[static_cast<std::size_t>(k + radius)] * in.at(sx, sy);
            }
            out.at(x, y) = sum;
        }
}

}  // namespace

std::uint64_t Random::next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double Random::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

// Box–Muller.
double Random::gaussian() {
    const double u = std::max(uniform(), 1e-12), v = uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

void Canvas::fill(double grey) {
    grey_.px.fill(static_cast<float>(grey));
    coverage_.px.fill(0.0f);
}

void Canvas::gradient(double grey_at_centre, double per_px_x, double per_px_y) {
    const double centre = (kFrameSize - 1) / 2.0;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            grey_.at(x, y) = static_cast<float>(grey_at_centre + per_px_x * (x - centre) + per_px_y * (y - centre));
    coverage_.px.fill(0.0f);
}

// Three octaves of value noise: random values on a grid of `cell_px`, smoothly interpolated.
void Canvas::texture(double mean, double amplitude, double cell_px, std::uint64_t seed) {
    coverage_.px.fill(0.0f);
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            double v = 0, weight = 0, cell = cell_px;
            for (int octave = 0; octave < 3; ++octave, cell *= 0.5) {
                const double fx = x / cell, fy = y / cell;
                const auto ix = static_cast<std::int64_t>(std::floor(fx)), iy = static_cast<std::int64_t>(std::floor(fy));
                const double tx = smooth(fx - static_cast<double>(ix)), ty = smooth(fy - static_cast<double>(iy));
                const std::uint64_t s = seed + octave;
                const double a = hash01(ix, iy, s), b = hash01(ix + 1, iy, s), c = hash01(ix, iy + 1, s),
                             d = hash01(ix + 1, iy + 1, s);
                const double w = 1.0 / (1 << octave);
                v += w * ((a * (1 - tx) + b * tx) * (1 - ty) + (c * (1 - tx) + d * tx) * ty);
                weight += w;
            }
            grey_.at(x, y) = static_cast<float>(mean + amplitude * (2 * v / weight - 1));
        }
}

void Canvas::rect(double x0, double y0, double x1, double y1, double grey) { paint(Box{x0, y0, x1, y1}, grey, false); }

void Canvas::line(double x0, double y0, double x1, double y1, double width_px, double grey) {
    paint(Capsule{x0, y0, x1, y1, width_px / 2}, grey, false);
}

void Canvas::clutter(int count, double grey_lo, double grey_hi, std::uint64_t seed) {
    Random layout(seed);
    for (int k = 0; k < count; ++k) {
        const double x = layout.uniform() * kFrameSize, y = layout.uniform() * kFrameSize;
        const double grey = grey_lo + layout.uniform() * (grey_hi - grey_lo);
        if (k % 3 == 0) {  // a long straight line at any angle
            const double angle = layout.uniform() * std::numbers::pi, half = 20 + layout.uniform() * 40;
            const double dx = half * std::cos(angle), dy = half * std::sin(angle);
            line(x - dx, y - dy, x + dx, y + dy, 1.5 + layout.uniform() * 2, grey);
        } else {
            const double w = 6 + layout.uniform() * 28, h = 6 + layout.uniform() * 28;
            rect(x - w / 2, y - h / 2, x + w / 2, y + h / 2, grey);
        }
    }
}

// Coverage by 4×4 supersampling of shape.inside() over the shape's bounding box only.
template <class Shape>
void Canvas::paint(const Shape& shape, double grey, bool target) {
    const Box b = shape.box();
    const int x0 = std::max(0, static_cast<int>(std::floor(b.x0))), x1 = std::min(kFrameSize - 1, static_cast<int>(std::ceil(b.x1)));
    const int y0 = std::max(0, static_cast<int>(std::floor(b.y0))), y1 = std::min(kFrameSize - 1, static_cast<int>(std::ceil(b.y1)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            int hits = 0;
            for (int j = 0; j < 4; ++j)
                for (int i = 0; i < 4; ++i) hits += shape.inside(x - 0.375 + 0.25 * i, y - 0.375 + 0.25 * j);
            if (hits == 0) continue;
            const float c = static_cast<float>(hits / 16.0);
            grey_.at(x, y) += c * (static_cast<float>(grey) - grey_.at(x, y));
            coverage_.at(x, y) = target ? std::max(coverage_.at(x, y), c) : coverage_.at(x, y) * (1 - c);
        }
}

template void Canvas::paint<Box>(const Box&, double, bool);
template void Canvas::paint<Disc>(const Disc&, double, bool);
template void Canvas::paint<Ellipse>(const Ellipse&, double, bool);
template void Canvas::paint<Capsule>(const Capsule&, double, bool);
template void Canvas::paint<Star>(const Star&, double, bool);
template void Canvas::paint<Walker>(const Walker&, double, bool);

void Canvas::occlude(double x0, double y0, double x1, double y1, double grey) { paint(Box{x0, y0, x1, y1}, grey, false); }

void Canvas::multiply_half_plane(double nx, double ny, double offset, double factor) {
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            const double s = std::clamp(nx * x + ny * y - offset + 0.5, 0.0, 1.0);
            grey_.at(x, y) *= static_cast<float>(1.0 + s * (factor - 1.0));
        }
}

void Canvas::gaussian_blur(double sigma_px) {
    const int radius = static_cast<int>(std::ceil(3 * sigma_px));
    std::vector<float> kernel(static_cast<std::size_t>(2 * radius + 1));
    double total = 0;
    for (int k = -radius; k <= radius; ++k) total += std::exp(-0.5 * k * k / (sigma_px * sigma_px));
    for (int k = -radius; k <= radius; ++k)
        kernel[static_cast<std::size_t>(k + radius)] = static_cast<float>(std::exp(-0.5 * k * k / (sigma_px * sigma_px)) / total);
    Plane<float> rows;
    convolve(grey_, rows, kernel, true);
    convolve(rows, grey_, kernel, false);
}

void Canvas::noise(double sigma, Random& random) {
    for (float& v : grey_.px) v += static_cast<float>(sigma * random.gaussian());
}

// The mask is coverage ≥ 0.5; the truth is that mask's pixel centroid and pixel count.
void Canvas::finish(SceneFrame& out) const {
    double area = 0, sx = 0, sy = 0;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            out.image.at(x, y) = static_cast<std::uint8_t>(std::clamp(std::lround(grey_.at(x, y)), 0l, 255l));
            const bool in = coverage_.at(x, y) >= 0.5f;
            out.mask.at(x, y) = in ? 255 : 0;
            if (in) {
                area += 1;
                sx += x;
                sy += y;
            }
        }
    out.truth = {area > 0 ? sx / area : 0, area > 0 ? sy / area : 0, area};
}

}  // namespace rays::scenes
