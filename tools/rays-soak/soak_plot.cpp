// SPDX-License-Identifier: Apache-2.0
#include "soak_plot.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "io/png_writer.hpp"

namespace rays::soak {
namespace {

constexpr int kWidth = 1200;
constexpr int kPanelHeight = 200;
constexpr int kPanels = 3;
using Rgb = std::array<std::uint8_t, 3>;
constexpr Rgb kUnit{30, 90, 200}, kTarget{220, 60, 40}, kError{30, 150, 60}, kAxis{170, 170, 170};

class Picture {
public:
    Picture() : px_(static_cast<std::size_t>(kWidth) * kPanelHeight * kPanels * 3, 255) {}
    void dot(int x, int y, Rgb c) {
        if (x < 0 || x >= kWidth || y < 0 || y >= kPanelHeight * kPanels) return;
        std::size_t i = (static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 3;
        px_[i] = c[0];
        px_[i + 1] = c[1];
        px_[i + 2] = c[2];
    }
    // One panel: each series drawn as a vertical span per column, scaled to the panel's range.
    template <class Value>
    void panel(int index, const std::vector<SoakFrame>& frames, Value value, Rgb colour, double lo, double hi) {
        const int top = index * kPanelHeight;
        auto row = [&](double v) { return top + kPanelHeight - 1 - static_cast<int>((v - lo) / (hi - lo) * (kPanelHeight - 1)); };
        for (int x = 0; x < kWidth; ++x) {
            std::size_t a = frames.size() * static_cast<std::size_t>(x) / kWidth;
            std::size_t b = std::max(a + 1, frames.size() * static_cast<std::size_t>(x + 1) / kWidth);
            double vmin = value(frames[a]), vmax = vmin;
            for (std::size_t k = a; k < b && k < frames.size(); ++k) {
                vmin = std::min(vmin, value(frames[k]));
                vmax = std::max(vmax, value(frames[k]));
            }
            for (int y = row(vmax); y <= row(vmin); ++y) dot(x, y, colour);
        }
    }
    void rule(int index, double v, double lo, double hi) {
        const int y = index * kPanelHeight + kPanelHeight - 1 - static_cast<int>((v - lo) / (hi - lo) * (kPanelHeight - 1));
        for (int x = 0; x < kWidth; x += 2) dot(x, y, kAxis);
    }
    const std::uint8_t* data() const { return px_.data(); }

private:
    std::vector<std::uint8_t> px_;
};

}  // namespace

bool write_plot(const std::string& path, const std::vector<SoakFrame>& frames, std::string& error) {
    if (frames.empty()) {
        error = "no frames to plot";
        return false;
    }
    Picture picture;
    auto range = [&](auto a, auto b) {
        double lo = 1e9, hi = -1e9;
        for (const SoakFrame& f : frames) {
            lo = std::min({lo, a(f), b(f)});
            hi = std::max({hi, a(f), b(f)});
        }
        return std::array<double, 2>{lo - 1, hi + 1};
    };
    auto pan = [](const SoakFrame& f) { return f.pan_deg; };
    auto az = [](const SoakFrame& f) { return f.target_az_deg; };
    auto tilt = [](const SoakFrame& f) { return f.tilt_deg; };
    auto el = [](const SoakFrame& f) { return f.target_el_deg; };
    auto err = [](const SoakFrame& f) { return std::hypot(f.target_az_deg - f.pan_deg, f.target_el_deg - f.tilt_deg); };
    auto [plo, phi] = range(pan, az);
    picture.panel(0, frames, az, kTarget, plo, phi);
    picture.panel(0, frames, pan, kUnit, plo, phi);
    auto [tlo, thi] = range(tilt, el);
    picture.panel(1, frames, el, kTarget, tlo, thi);
    picture.panel(1, frames, tilt, kUnit, tlo, thi);
    auto [elo, ehi] = range(err, err);
    picture.rule(2, 0.0, std::min(elo, 0.0), ehi);
    picture.panel(2, frames, err, kError, std::min(elo, 0.0), ehi);
    return io::write_png(path, kWidth, kPanelHeight * kPanels, 3, picture.data(), error);
}

bool write_trace(const std::string& path, const std::vector<SoakFrame>& frames, std::string& error) {
    std::FILE* file = std::fopen(path.c_str(), "w");
    if (file == nullptr) {
        error = std::strerror(errno);
        return false;
    }
    std::fprintf(file, "t_s,in_image,truth_x,truth_y,has_contour,contour_x,contour_y,on_target,speed_deg_s,"
                       "pan_deg,tilt_deg,target_az_deg,target_el_deg,latency_us\n");
    for (const SoakFrame& f : frames)
        std::fprintf(file, "%.3f,%d,%.2f,%.2f,%d,%.2f,%.2f,%d,%.2f,%.3f,%.3f,%.3f,%.3f,%.0f\n", f.t_s,
                     f.target_in_image ? 1 : 0, f.truth_px.x, f.truth_px.y, f.has_contour ? 1 : 0, f.contour_px.x,
                     f.contour_px.y, on_target(f) ? 1 : 0, f.speed_deg_s, f.pan_deg, f.tilt_deg, f.target_az_deg,
                     f.target_el_deg, static_cast<double>(f.latency_us));
    if (std::fclose(file) != 0) {
        error = std::strerror(errno);
        return false;
    }
    return true;
}

}  // namespace rays::soak
