// SPDX-License-Identifier: Apache-2.0
#include "io/png_writer.hpp"

#include <png.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "io/stdio_file.hpp"

namespace rays::io {
namespace {

void on_png_error(png_structp png, png_const_charp) { png_longjmp(png, 1); }
void on_png_warning(png_structp, png_const_charp) {}

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + length);
}

void flush_nothing(png_structp) {}

class PngWriteStruct {
public:
    PngWriteStruct()
        : png_(png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, on_png_error, on_png_warning)),
          info_(png_ ? png_create_info_struct(png_) : nullptr) {}
    ~PngWriteStruct() { png_destroy_write_struct(&png_, &info_); }
    PngWriteStruct(const PngWriteStruct&) = delete;
    PngWriteStruct& operator=(const PngWriteStruct&) = delete;

    png_structp png() const { return png_; }
    png_infop info() const { return info_; }

private:
    png_structp png_;
    png_infop info_;
};

// Only trivially destructible locals here: libpng's longjmp must not skip a destructor.
bool write_rows(png_structp png, png_infop info, int w, int h, int channels, const std::uint8_t* data,
                std::vector<std::uint8_t>* out) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, out, append_bytes, flush_nothing);
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8,
                 channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const std::size_t row_bytes = static_cast<std::size_t>(w) * static_cast<std::size_t>(channels);
    for (int y = 0; y < h; ++y) png_write_row(png, data + static_cast<std::size_t>(y) * row_bytes);
    png_write_end(png, info);
    return true;
}

}  // namespace

bool encode_png(int w, int h, int channels, const std::uint8_t* data, std::vector<std::uint8_t>& out) {
    out.clear();
    if (w < 1 || h < 1 || (channels != 1 && channels != 3) || data == nullptr) return false;
    PngWriteStruct writer;
    return writer.info() && write_rows(writer.png(), writer.info(), w, h, channels, data, &out);
}

bool write_png(const std::string& path, int w, int h, int channels, const std::uint8_t* data, std::string& error) {
    std::vector<std::uint8_t> encoded;
    if (!encode_png(w, h, channels, data, encoded)) {
        error = path + ": cannot encode a " + std::to_string(w) + "x" + std::to_string(h) + " PNG with " +
                std::to_string(channels) + " channels";
        return false;
    }
    StdioFile file(std::fopen(path.c_str(), "wb"));
    if (!file) {
        error = path + ": cannot create: " + std::strerror(errno);
        return false;
    }
    const bool written = std::fwrite(encoded.data(), 1, encoded.size(), file.get()) == encoded.size();
    const int write_errno = errno;
    const bool closed = std::fclose(file.release()) == 0;
    if (!written || !closed) {
        error = path + ": cannot write: " + std::strerror(written ? errno : write_errno);
        return false;
    }
    return true;
}

}  // namespace rays::io
