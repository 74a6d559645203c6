// SPDX-License-Identifier: Apache-2.0
#include "io/overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace rays::io {
namespace {

bool finite(Point p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Nearest integer, limited so that far-off points cannot overflow an int.
int to_pixel(double v) { return static_cast<int>(std::lround(std::clamp(v, -1e6, 1e6))); }

// Liang–Barsky: shrinks [t0, t1] along a + t·d to the part where lo <= coordinate <= hi.
bool clip_axis(double a, double d, double lo, double hi, double& t0, double& t1) {
    const double p[2] = {-d, d};
    const double q[2] = {a - lo, hi - a};
    for (int k = 0; k < 2; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double t = q[k] / p[k];
        if (p[k] < 0.0) t0 = std::max(t0, t);
        else t1 = std::min(t1, t);
    }
    return t0 <= t1;
}

}  // namespace

RgbCanvas::RgbCanvas(const GreyImage& img, int zoom)
    : zoom_(std::max(1, zoom)), size_(kFrameSize * zoom_), rgb_(static_cast<std::size_t>(size_) * size_ * 3) {
    set_image(img);
}

void RgbCanvas::set_image(const GreyImage& img) {
    for (int y = 0; y < size_; ++y) {
        const std::uint8_t* src = img.row(y / zoom_);
        std::uint8_t* dst = &rgb_[static_cast<std::size_t>(y) * size_ * 3];
        for (int x = 0; x < size_; ++x) dst[3 * x] = dst[3 * x + 1] = dst[3 * x + 2] = src[x / zoom_];
    }
}

RgbCanvas::RgbCanvas(const GreyImage& img, const Chroma& chroma, int zoom)
    : zoom_(std::max(1, zoom)), size_(kFrameSize * zoom_), rgb_(static_cast<std::size_t>(size_) * size_ * 3) {
    set_image(img, chroma);
}

Rgb ycbcr_to_rgb(std::uint8_t y, std::uint8_t cb, std::uint8_t cr) {
    const double b_ = cb - 128.0, r_ = cr - 128.0;
    const auto clamp = [](double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); };
    return {clamp(y + 1.402 * r_), clamp(y - 0.344136 * b_ - 0.714136 * r_), clamp(y + 1.772 * b_)};
}

void RgbCanvas::set_image(const GreyImage& img, const Chroma& chroma) {
    if (!chroma.present) return set_image(img);
    for (int y = 0; y < size_; ++y) {
        const int py = y / zoom_;
        const std::uint8_t* src = img.row(py);
        std::uint8_t* dst = &rgb_[static_cast<std::size_t>(y) * size_ * 3];
        for (int x = 0; x < size_; ++x) {
            const int px = x / zoom_;
            const Rgb c = ycbcr_to_rgb(src[px], chroma.u_at(px / 2, py / 2), chroma.v_at(px / 2, py / 2));
            dst[3 * x] = c.r;
            dst[3 * x + 1] = c.g;
            dst[3 * x + 2] = c.b;
        }
    }
}

void RgbCanvas::plot(int x, int y, Rgb c) {
    if (x < 0 || y < 0 || x >= size_ || y >= size_) return;
    std::uint8_t* px = &rgb_[(static_cast<std::size_t>(y) * size_ + x) * 3];
    px[0] = c.r;
    px[1] = c.g;
    px[2] = c.b;
}

// Clip in canvas coordinates to the pixel area, then Bresenham between the nearest pixels.
void RgbCanvas::line(Point a, Point b, Rgb c) {
    if (!finite(a) || !finite(b)) return;
    const double ax = to_canvas(a.x), ay = to_canvas(a.y);
    const double dx = to_canvas(b.x) - ax, dy = to_canvas(b.y) - ay;
    const double hi = size_ - 0.5;
    double t0 = 0.0, t1 = 1.0;
    if (!clip_axis(ax, dx, -0.5, hi, t0, t1) || !clip_axis(ay, dy, -0.5, hi, t0, t1)) return;
    const int last = size_ - 1;
    int x0 = std::clamp(to_pixel(ax + t0 * dx), 0, last), y0 = std::clamp(to_pixel(ay + t0 * dy), 0, last);
    const int x1 = std::clamp(to_pixel(ax + t1 * dx), 0, last), y1 = std::clamp(to_pixel(ay + t1 * dy), 0, last);
    const int step_x = x0 < x1 ? 1 : -1, step_y = y0 < y1 ? 1 : -1;
    const int ex = std::abs(x1 - x0), ey = -std::abs(y1 - y0);
    for (int err = ex + ey;;) {
        plot(x0, y0, c);
        if (x0 == x1 && y0 == y1) break;
        const int e2 = 2 * err;
        if (e2 >= ey) { err += ey; x0 += step_x; }
        if (e2 <= ex) { err += ex; y0 += step_y; }
    }
}

void RgbCanvas::polygon(const std::vector<Point>& pts, Rgb c) {
    if (pts.size() == 1) dot(pts.front(), c);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) line(pts[i], pts[i + 1], c);
    if (pts.size() > 2) line(pts.back(), pts.front(), c);
}

void RgbCanvas::cross(Point p, int half, Rgb c) {
    if (!finite(p)) return;
    const int cx = to_pixel(to_canvas(p.x)), cy = to_pixel(to_canvas(p.y));
    half = std::clamp(half, 0, size_);
    for (int d = -half; d <= half; ++d) {
        plot(cx + d, cy, c);
        plot(cx, cy + d, c);
    }
}

void RgbCanvas::dot(Point p, Rgb c) {
    if (!finite(p)) return;
    const int x0 = to_pixel(to_canvas(p.x) - (zoom_ - 1) * 0.5), y0 = to_pixel(to_canvas(p.y) - (zoom_ - 1) * 0.5);
    for (int y = y0; y < y0 + zoom_; ++y)
        for (int x = x0; x < x0 + zoom_; ++x) plot(x, y, c);
}

}  // namespace rays::io
