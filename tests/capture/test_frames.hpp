// SPDX-License-Identifier: Apache-2.0
// Frames for the fake driver: drawn luma patterns packed as GREY or YUYV, and JPEGs made with
// libjpeg-turbo's compressor.
#pragma once
#include <cstdint>
#include <functional>
#include <vector>

#include "core/image.hpp"
#include "io/area_scaler.hpp"

namespace rays::test {

// A luma image, stride = width.
struct Luma {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> px;

    Luma(int w, int h, const std::function<std::uint8_t(int, int)>& value);
    std::uint8_t at(int x, int y) const { return px[static_cast<std::size_t>(y * width + x)]; }
};

// Smooth gradients with a few large blocks: survives JPEG and area averaging recognisably.
std::uint8_t pattern(int x, int y, int width, int height);
Luma draw_pattern(int width, int height);

std::vector<std::uint8_t> pack_grey(const Luma& luma, int line_padding = 0);
// Chroma bytes are set far from the luma so a converter reading them shows.
std::vector<std::uint8_t> pack_yuyv(const Luma& luma, int line_padding = 0);

// Baseline JPEG, 4:2:2 YCbCr from RGB = (luma, luma, luma), as a UVC camera would send.
std::vector<std::uint8_t> encode_jpeg(const Luma& luma, int quality = 95);
// A 4:2:2 colour JPEG of one colour per pixel.
std::vector<std::uint8_t> encode_rgb_jpeg(int width, int height, const std::function<std::uint32_t(int, int)>& rgb);
// Removes the DHT segments, as MJPEG cameras leave out the standard Huffman tables.
std::vector<std::uint8_t> strip_huffman_tables(const std::vector<std::uint8_t>& jpeg);

// What the camera should deliver for a luma source: the AreaScaler over the same pixels.
GreyImage area_scaled(const Luma& luma, io::Crop crop = {});

// Mean absolute difference of two processing frames.
double mean_abs_diff(const GreyImage& a, const GreyImage& b);

}  // namespace rays::test
