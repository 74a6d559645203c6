// SPDX-License-Identifier: Apache-2.0
// The simulated camera's static world: an equirectangular grey panorama over the full circle of
// azimuth (−180…180°) and a band of elevation around the horizon, generated from a seed or loaded
// from a PNG, and looked up bilinearly by world angles. Allocated once, when made.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rays::sim {

class Panorama {
public:
    // A world of sky, ground with a wavy horizon, value-noise texture, buildings and poles, at
    // px_per_deg pixels per degree over elevation −60…+60°.
    static Panorama generate(std::uint64_t seed, double px_per_deg = 4.0);
    // Any PNG: its width spans the full circle of azimuth, its rows the same angle per pixel, centred
    // on the horizon. nullopt with `error` set when the file cannot be read.
    static std::optional<Panorama> load_png(const std::string& path, std::string& error);

    // Grey level (0…255) seen in a world direction: azimuth wraps round, elevation beyond the
    // panorama's band takes its top or bottom row.
    double grey(double azimuth_rad, double elevation_rad) const;

    int width() const { return width_; }
    int height() const { return height_; }
    double px_per_rad() const { return px_per_rad_; }

private:
    Panorama(int width, int height, std::vector<float> grey);
    int width_;
    int height_;
    double px_per_rad_;        // the same along both axes
    double top_elevation_rad_;  // of row 0's upper edge
    std::vector<float> grey_;   // row-major, row 0 at the top
};

}  // namespace rays::sim
