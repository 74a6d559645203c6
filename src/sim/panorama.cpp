// SPDX-License-Identifier: Apache-2.0
#include "sim/panorama.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/png_decoder.hpp"
#include "scenes/render.hpp"
#include "sim/value_noise.hpp"

namespace rays::sim {
namespace {

constexpr double kElevationSpanDeg = 120;  // generated panoramas: −60…+60°

// Draws into a generated panorama in degrees, with exact area coverage at pixel edges.
class PanoramaPainter {
public:
    PanoramaPainter(int width, int height, double px_per_deg, std::vector<float>& grey)
        : width_(width), height_(height), px_per_deg_(px_per_deg), grey_(grey) {}

    double azimuth_deg(int column) const { return -180.0 + (column + 0.5) / px_per_deg_; }
    double elevation_deg(int row) const { return kElevationSpanDeg / 2 - (row + 0.5) / px_per_deg_; }
    float& at(int column, int row) { return grey_[static_cast<std::size_t>(row) * width_ + column]; }

    // An upright rectangle; azimuths may run past ±180° and wrap round.
    void rect(double azimuth_lo, double azimuth_hi, double elevation_lo, double elevation_hi, double grey) {
        const double x0 = (azimuth_lo + 180.0) * px_per_deg_, x1 = (azimuth_hi + 180.0) * px_per_deg_;
        const double y0 = (kElevationSpanDeg / 2 - elevation_hi) * px_per_deg_;
        const double y1 = (kElevationSpanDeg / 2 - elevation_lo) * px_per_deg_;
        const int row_lo = std::max(0, static_cast<int>(std::floor(y0)));
        const int row_hi = std::min(height_ - 1, static_cast<int>(std::floor(y1)));
        for (int column = static_cast<int>(std::floor(x0)); column <= static_cast<int>(std::floor(x1)); ++column) {
            const double cover_x = overlap(column, x0, x1);
            const int wrapped = ((column % width_) + width_) % width_;
            for (int row = row_lo; row <= row_hi; ++row) {
                const double cover = cover_x * overlap(row, y0, y1);
                float& pixel = at(wrapped, row);
                pixel = static_cast<float>(pixel + cover * (grey - pixel));
            }
        }
    }

private:
    // How much of pixel [i, i + 1) lies within [lo, hi].
    static double overlap(int i, double lo, double hi) { return std::max(0.0, std::min(hi, i + 1.0) - std::max(lo, double(i))); }

    int width_, height_;
    double px_per_deg_;
    std::vector<float>& grey_;
};

// Elevation of the horizon at an azimuth, deg: gently rolling between about −1 and +4°.
double horizon_deg(double azimuth_deg, std::uint64_t seed) {
    constexpr std::int64_t kCells = 12;  // one lattice cell per 30°, wrapping round the circle
    return 1.5 + 5.0 * (fractal_noise((azimuth_deg + 180.0) / 30.0, 0.5, seed, 2, kCells) - 0.5);
}

// Sky brightening upward, ground darkening downward, both with value-noise texture.
void paint_land_and_sky(PanoramaPainter& painter, int width, int height, std::uint64_t seed) {
    constexpr double kTextureCellDeg = 8.0;
    constexpr auto kCellsRound = static_cast<std::int64_t>(360.0 / kTextureCellDeg);
    for (int column = 0; column < width; ++column) {
        const double azimuth = painter.azimuth_deg(column);
        const double horizon = horizon_deg(azimuth, seed);
        const double u = (azimuth + 180.0) / kTextureCellDeg;
        for (int row = 0; row < height; ++row) {
            const double elevation = painter.elevation_deg(row), v = elevation / kTextureCellDeg;
            const double texture = fractal_noise(u, v, seed + 1, 3, kCellsRound) - 0.5;
            const double sky = 170.0 + 0.6 * (elevation - horizon) + 30.0 * texture;
            const double ground = 110.0 + 0.8 * (elevation - horizon) + 90.0 * texture;
            const double sky_share = std::clamp((elevation - horizon) * 2.0 + 0.5, 0.0, 1.0);  // ½° soft edge
            painter.at(column, row) = static_cast<float>(ground + sky_share * (sky - ground));
        }
    }
}

// Buildings standing on the horizon, with a band of a different grey, and thin dark poles.
void paint_clutter(PanoramaPainter& painter, std::uint64_t seed) {
    scenes::Random random(seed + 2);
    for (int i = 0; i < 22; ++i) {
        const double azimuth = -180.0 + 360.0 * random.uniform(), width = 3.0 + 11.0 * random.uniform();
        const double top = horizon_deg(azimuth, seed) + 2.0 + 14.0 * random.uniform();
        const double grey = 60.0 + 140.0 * random.uniform();
        painter.rect(azimuth, azimuth + width, -6.0, top, grey);
        const double band = top - (1.0 + 4.0 * random.uniform());
        painter.rect(azimuth + 0.5, azimuth + width - 0.5, band - 1.0, band, grey + (random.uniform() < 0.5 ? -40.0 : 40.0));
    }
    for (int i = 0; i < 14; ++i) {
        const double azimuth = -180.0 + 360.0 * random.uniform(), width = 0.25 + 0.35 * random.uniform();
        painter.rect(azimuth, azimuth + width, -40.0, 4.0 + 26.0 * random.uniform(), 30.0 + 60.0 * random.uniform());
    }
}

}  // namespace

Panorama::Panorama(int width, int height, std::vector<float> grey)
    : width_(width),
      height_(height),
      px_per_rad_(width / (2.0 * std::numbers::pi)),
      top_elevation_rad_(height / 2.0 / px_per_rad_),
      grey_(std::move(grey)) {}

Panorama Panorama::generate(std::uint64_t seed, double px_per_deg) {
    const int width = static_cast<int>(std::lround(360.0 * px_per_deg));
    const int height = static_cast<int>(std::lround(kElevationSpanDeg * px_per_deg));
    std::vector<float> grey(static_cast<std::size_t>(width) * height);
    PanoramaPainter painter(width, height, px_per_deg, grey);
    paint_land_and_sky(painter, width, height, seed);
    paint_clutter(painter, seed);
    for (float& g : grey) g = std::clamp(g, 0.0f, 255.0f);
    return Panorama(width, height, std::move(grey));
}

std::optional<Panorama> Panorama::load_png(const std::string& path, std::string& error) {
    io::PngDecoder decoder;
    io::SourceImage image;
    if (!decoder.decode(path, image, error)) return std::nullopt;
    if (image.width < 2 || image.height < 2) {
        error = path + ": a panorama needs at least 2×2 pixels";
        return std::nullopt;
    }
    return Panorama(image.width, image.height, std::vector<float>(image.grey.begin(), image.grey.end()));
}

double Panorama::grey(double azimuth_rad, double elevation_rad) const {
    if (azimuth_rad < -std::numbers::pi || azimuth_rad > std::numbers::pi)
        azimuth_rad = std::remainder(azimuth_rad, 2.0 * std::numbers::pi);
    const double x = (azimuth_rad + std::numbers::pi) * px_per_rad_ - 0.5;
    const double y = std::clamp((top_elevation_rad_ - elevation_rad) * px_per_rad_ - 0.5, 0.0, height_ - 1.0);
    const double fx = std::floor(x), fy = std::floor(y);
    int x0 = static_cast<int>(fx), x1 = x0 + 1;
    if (x0 < 0) x0 += width_;
    if (x1 >= width_) x1 -= width_;
    const int y0 = static_cast<int>(fy), y1 = std::min(y0 + 1, height_ - 1);
    const double tx = x - fx, ty = y - fy;
    const float* top = grey_.data() + static_cast<std::size_t>(y0) * width_;
    const float* bottom = grey_.data() + static_cast<std::size_t>(y1) * width_;
    const double upper = top[x0] + tx * (top[x1] - top[x0]), lower = bottom[x0] + tx * (bottom[x1] - bottom[x0]);
    return upper + ty * (lower - upper);
}

}  // namespace rays::sim
