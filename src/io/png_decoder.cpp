// SPDX-License-Identifier: Apache-2.0
#include "io/png_decoder.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/stdio_file.hpp"

namespace rays::io {
namespace {

constexpr png_uint_32 kMaxSide = 8192;

// libpng reports errors by calling this and never returning; we keep the text and jump back.
struct PngErrorText {
    char text[256] = {};
};

void on_png_error(png_structp png, png_const_charp message) {
    auto* sink = static_cast<PngErrorText*>(png_get_error_ptr(png));
    std::snprintf(sink->text, sizeof sink->text, "%s", message);
    png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

class PngReadStruct {
public:
    explicit PngReadStruct(PngErrorText& errors)
        : png_(png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning)),
          info_(png_ ? png_create_info_struct(png_) : nullptr) {}
    ~PngReadStruct() { png_destroy_read_struct(&png_, &info_, nullptr); }
    PngReadStruct(const PngReadStruct&) = delete;
    PngReadStruct& operator=(const PngReadStruct&) = delete;

    png_structp png() const { return png_; }
    png_infop info() const { return info_; }

private:
    png_structp png_;
    png_infop info_;
};

struct PngLayout {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    png_byte channels = 0;  // 1 (grey) or 3 (RGB) after the transformations below
};

// The setjmp functions hold only trivially destructible locals, so libpng's longjmp skips no destructor.
bool read_layout(png_structp png, png_infop info, std::FILE* file, PngLayout& layout) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_read_info(png, info);
    png_set_scale_16(png);                 // 16 → 8 bits with rounding
    png_set_palette_to_rgb(png);           // palette → RGB
    png_set_expand_gray_1_2_4_to_8(png);   // 1, 2, 4-bit grey → 8-bit
    png_set_strip_alpha(png);              // alpha (and tRNS, which we never expand) is ignored
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    layout.width = png_get_image_width(png, info);
    layout.height = png_get_image_height(png, info);
    layout.channels = png_get_channels(png, info);
    return true;
}

bool read_rows(png_structp png, png_infop info, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, info);
    return true;
}

// Rec.601 luma, Y = 0.299 R + 0.587 G + 0.114 B, rounded; grey (R = G = B) maps onto itself.
std::uint8_t rec601_luma(const std::uint8_t* rgb) {
    return static_cast<std::uint8_t>((299 * rgb[0] + 587 * rgb[1] + 114 * rgb[2] + 500) / 1000);
}

}  // namespace

bool PngDecoder::decode(const std::string& path, SourceImage& out, std::string& error) {
    StdioFile file(std::fopen(path.c_str(), "rb"));
    if (!file) {
        error = path + ": cannot open: " + std::strerror(errno);
        return false;
    }
    PngErrorText errors;
    PngReadStruct reader(errors);
    if (!reader.info()) {
        error = path + ": libpng could not start";
        return false;
    }
    PngLayout layout;
    if (!read_layout(reader.png(), reader.info(), file.get(), layout)) {
        error = path + ": " + errors.text;
        return false;
    }
    if (layout.width > kMaxSide || layout.height > kMaxSide || (layout.channels != 1 && layout.channels != 3)) {
        error = path + ": unsupported PNG (" + std::to_string(layout.width) + "x" + std::to_string(layout.height) +
                ", " + std::to_string(layout.channels) + " channels)";
        return false;
    }
    const std::size_t w = layout.width;
    const std::size_t h = layout.height;
    const std::size_t row_bytes = w * layout.channels;
    pixels_.resize(row_bytes * h);
    rows_.resize(h);
    for (std::size_t y = 0; y < h; ++y) rows_[y] = pixels_.data() + y * row_bytes;
    if (!read_rows(reader.png(), reader.info(), rows_.data())) {
        error = path + ": " + errors.text;
        return false;
    }
    out.width = static_cast<int>(w);
    out.height = static_cast<int>(h);
    out.grey.resize(w * h);
    if (layout.channels == 1) {
        std::memcpy(out.grey.data(), pixels_.data(), w * h);
    } else {
        for (std::size_t i = 0; i < w * h; ++i) out.grey[i] = rec601_luma(&pixels_[3 * i]);
    }
    return true;
}

}  // namespace rays::io
