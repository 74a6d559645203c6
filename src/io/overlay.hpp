// SPDX-License-Identifier: Apache-2.0
// An RGB copy of a processing frame, enlarged by an integer zoom, to draw contours and markers on.
// Drawing coordinates are processing pixels (centres at integers); processing pixel (x, y) becomes the
// zoom×zoom block whose centre is (x·zoom + (zoom−1)/2, y·zoom + (zoom−1)/2) on the canvas.
#pragma once
#include <cstdint>
#include <vector>

#include "core/image.hpp"

namespace rays::io {

struct Rgb {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
};

// Full-range BT.601 (JPEG's, and the realset's C420jpeg) Y Cb Cr to RGB.
Rgb ycbcr_to_rgb(std::uint8_t y, std::uint8_t cb, std::uint8_t cr);

class RgbCanvas {
public:
    RgbCanvas(const GreyImage& img, int zoom);  // zoom below 1 is taken as 1
    // In colour where `chroma` is present (each chroma pixel colours its 2×2 processing pixels).
    RgbCanvas(const GreyImage& img, const Chroma& chroma, int zoom);

    // Repaints the canvas with a new frame, keeping its buffer.
    void set_image(const GreyImage& img);
    void set_image(const GreyImage& img, const Chroma& chroma);

    // Drawing clips to the canvas; points that are not finite draw nothing.
    void line(Point a, Point b, Rgb c);
    void polygon(const std::vector<Point>& pts, Rgb c);  // closed: the last point joins the first
    void cross(Point p, int half, Rgb c);                // '+' with arms of `half` canvas pixels
    void dot(Point p, Rgb c);                            // the zoom×zoom block centred on p

    int width() const { return size_; }
    int height() const { return size_; }
    int zoom() const { return zoom_; }
    const std::vector<std::uint8_t>& rgb() const { return rgb_; }  // rows of width·3 bytes

private:
    double to_canvas(double v) const { return v * zoom_ + (zoom_ - 1) * 0.5; }
    void plot(int x, int y, Rgb c);

    int zoom_;
    int size_;
    std::vector<std::uint8_t> rgb_;
};

}  // namespace rays::io
