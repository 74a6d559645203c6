// SPDX-License-Identifier: Apache-2.0
#include "test_frames.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <jpeglib.h>

namespace rays::test {

Luma::Luma(int w, int h, const std::function<std::uint8_t(int, int)>& value)
    : width(w), height(h), px(static_cast<std::size_t>(w * h)) {
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) px[static_cast<std::size_t>(y * w + x)] = value(x, y);
}

std::uint8_t pattern(int x, int y, int width, int height) {
    const double u = static_cast<double>(x) / width;
    const double v = static_cast<double>(y) / height;
    double value = 40.0 + 120.0 * u + 60.0 * v;
    if (u > 0.2 && u < 0.45 && v > 0.25 && v < 0.6) value = 235.0;  // bright block
    if (u > 0.6 && u < 0.85 && v > 0.5 && v < 0.8) value = 10.0;    // dark block
    return static_cast<std::uint8_t>(std::lround(value));
}

Luma draw_pattern(int width, int height) {
    return Luma(width, height, [&](int x, int y) { return pattern(x, y, width, height); });
}

std::vector<std::uint8_t> pack_grey(const Luma& luma, int line_padding) {
    const int pitch = luma.width + line_padding;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(pitch * luma.height), 0x5a);
    for (int y = 0; y < luma.height; ++y)
        for (int x = 0; x < luma.width; ++x) out[static_cast<std::size_t>(y * pitch + x)] = luma.at(x, y);
    return out;
}

std::vector<std::uint8_t> pack_yuyv(const Luma& luma, int line_padding) {
    const int pitch = 2 * luma.width + line_padding;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(pitch * luma.height), 0x5a);
    for (int y = 0; y < luma.height; ++y)
        for (int x = 0; x < luma.width; ++x) {
            const auto i = static_cast<std::size_t>(y * pitch + 2 * x);
            out[i] = luma.at(x, y);
            out[i + 1] = static_cast<std::uint8_t>(luma.at(x, y) ^ 0x80);  // U or V
        }
    return out;
}

namespace {

// Compresses rows of RGB; a libjpeg error here is a broken test, so it aborts loudly.
std::vector<std::uint8_t> compress(int width, int height, const std::vector<std::uint8_t>& rgb, int quality) {
    jpeg_compress_struct info{};
    jpeg_error_mgr error{};
    info.err = jpeg_std_error(&error);
    jpeg_create_compress(&info);
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    jpeg_mem_dest(&info, &buffer, &size);
    info.image_width = static_cast<JDIMENSION>(width);
    info.image_height = static_cast<JDIMENSION>(height);
    info.input_components = 3;
    info.in_color_space = JCS_RGB;
    jpeg_set_defaults(&info);
    jpeg_set_quality(&info, quality, TRUE);
    info.comp_info[0].h_samp_factor = 2;  // 4:2:2
    info.comp_info[0].v_samp_factor = 1;
    jpeg_start_compress(&info, TRUE);
    while (info.next_scanline < info.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(rgb.data() + static_cast<std::size_t>(info.next_scanline) * 3 * width);
        jpeg_write_scanlines(&info, &row, 1);
    }
    jpeg_finish_compress(&info);
    std::vector<std::uint8_t> out(buffer, buffer + size);
    std::free(buffer);
    jpeg_destroy_compress(&info);
    return out;
}

}  // namespace

std::vector<std::uint8_t> encode_jpeg(const Luma& luma, int quality) {
    std::vector<std::uint8_t> rgb(luma.px.size() * 3);
    for (std::size_t i = 0; i < luma.px.size(); ++i) rgb[3 * i] = rgb[3 * i + 1] = rgb[3 * i + 2] = luma.px[i];
    return compress(luma.width, luma.height, rgb, quality);
}

std::vector<std::uint8_t> encode_rgb_jpeg(int width, int height, const std::function<std::uint32_t(int, int)>& rgb) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(width * height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::uint32_t c = rgb(x, y);
            const auto i = static_cast<std::size_t>(y * width + x) * 3;
            px[i] = static_cast<std::uint8_t>(c >> 16);
            px[i + 1] = static_cast<std::uint8_t>(c >> 8);
            px[i + 2] = static_cast<std::uint8_t>(c);
        }
    return compress(width, height, px, 95);
}

// Walks the marker segments before the scan; each segment after SOI is FF xx, then a big-endian
// length that counts itself.
std::vector<std::uint8_t> strip_huffman_tables(const std::vector<std::uint8_t>& jpeg) {
    std::vector<std::uint8_t> out(jpeg.begin(), jpeg.begin() + 2);
    std::size_t at = 2;
    while (at + 4 <= jpeg.size() && jpeg[at] == 0xff && jpeg[at + 1] != 0xda) {
        const std::size_t length = 2 + (static_cast<std::size_t>(jpeg[at + 2]) << 8 | jpeg[at + 3]);
        if (jpeg[at + 1] != 0xc4) out.insert(out.end(), jpeg.begin() + static_cast<std::ptrdiff_t>(at),
                                             jpeg.begin() + static_cast<std::ptrdiff_t>(at + length));
        at += length;
    }
    out.insert(out.end(), jpeg.begin() + static_cast<std::ptrdiff_t>(at), jpeg.end());
    return out;
}

GreyImage area_scaled(const Luma& luma, io::Crop crop) {
    std::string error;
    const auto scaler = io::AreaScaler::make(luma.width, luma.height, crop, error);
    if (!scaler) {
        std::fprintf(stderr, "area_scaled: %s\n", error.c_str());
        std::abort();
    }
    GreyImage out;
    scaler->scale(luma.px.data(), luma.width, out);
    return out;
}

double mean_abs_diff(const GreyImage& a, const GreyImage& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i < a.px.size(); ++i) sum += std::abs(static_cast<int>(a.px[i]) - static_cast<int>(b.px[i]));
    return sum / static_cast<double>(a.px.size());
}

}  // namespace rays::test
