// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <png.h>

#include <cstdio>
#include <string>
#include <vector>

#include "io/frame_reader.hpp"
#include "io/image_folder_reader.hpp"
#include "io/png_writer.hpp"
#include "support/temp_dir.hpp"

using rays::io::FrameReader;
using rays::io::open_frames;
using rays::io::SourceImage;
using Status = FrameReader::Status;

namespace {

std::vector<std::uint8_t> ramp(int w, int h, int seed) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h));
    for (std::size_t i = 0; i < px.size(); ++i) px[i] = static_cast<std::uint8_t>(i * 37 + static_cast<std::size_t>(seed) * 5);
    return px;
}

std::string p5(int w, int h, int maxval, const std::vector<int>& samples) {
    std::string out = "P5\n# written by the test\n" + std::to_string(w) + " " + std::to_string(h) + "\n" +
                      std::to_string(maxval) + "\n";
    for (int v : samples) {
        if (maxval > 255) out += static_cast<char>(v >> 8);
        out += static_cast<char>(v & 0xFF);
    }
    return out;
}

// Writes a PNG of any colour type and bit depth straight through libpng; rows are packed as libpng expects.
void write_raw_png(const std::string& path, int w, int h, int colour_type, int bit_depth,
                   const std::vector<std::uint8_t>& packed, const std::vector<png_color>& palette = {}) {
    std::FILE* file = std::fopen(path.c_str(), "wb");
    REQUIRE(file != nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) FAIL("libpng could not write " << path);
    png_init_io(png, file);
    png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), bit_depth, colour_type,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (!palette.empty()) png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    png_write_info(png, info);
    const std::size_t row = packed.size() / static_cast<std::size_t>(h);
    for (int y = 0; y < h; ++y) png_write_row(png, packed.data() + static_cast<std::size_t>(y) * row);
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
}

SourceImage read_single(const std::string& dir) {
    auto opened = open_frames(dir);
    INFO(opened.error);
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(opened.reader->next(img) == Status::End);
    return img;
}

}  // namespace

TEST_CASE("a folder of 8-bit P5 files reads back exactly, sorted by name, other files ignored") {
    rays::test::TempDir dir;
    for (int f = 2; f >= 0; --f) {
        std::vector<int> samples;
        for (auto v : ramp(7, 5, f)) samples.push_back(v);
        dir.write("frame_00" + std::to_string(f) + ".pgm", p5(7, 5, 255, samples));
    }
    dir.write("notes.txt", "not a frame");
    auto opened = open_frames(dir.path().string());
    REQUIRE(opened.reader);
    CHECK(opened.reader->width() == 7);
    CHECK(opened.reader->height() == 5);
    CHECK(opened.reader->fps() == 0.0);
    SourceImage img;
    for (int f = 0; f < 3; ++f) {
        REQUIRE(opened.reader->next(img) == Status::Frame);
        CHECK(img.width == 7);
        CHECK(img.grey == ramp(7, 5, f));
    }
    CHECK(opened.reader->next(img) == Status::End);
    CHECK(opened.reader->next(img) == Status::End);
}

TEST_CASE("16-bit and other maxval PGM samples scale to 8 bits with rounding") {
    rays::test::TempDir dir;
    dir.write("a.pgm", p5(4, 1, 65535, {0, 128 * 257, 255 * 257, 65535}));
    CHECK(read_single(dir.path().string()).grey == std::vector<std::uint8_t>{0, 128, 255, 255});

    rays::test::TempDir ten_bit;
    ten_bit.write("a.pgm", p5(3, 1, 1023, {0, 512, 1023}));
    CHECK(read_single(ten_bit.path().string()).grey == std::vector<std::uint8_t>{0, 128, 255});

    rays::test::TempDir four_bit;
    four_bit.write("a.pgm", p5(2, 1, 15, {1, 15}));
    CHECK(read_single(four_bit.path().string()).grey == std::vector<std::uint8_t>{17, 255});
}

TEST_CASE("ASCII P2 with comments reads back exactly") {
    rays::test::TempDir dir;
    dir.write("a.pgm", "P2\n# comment\n3 2 # trailing comment\n255\n0 1 2\n# between rows\n253 254\n255\n");
    const SourceImage img = read_single(dir.path().string());
    CHECK(img.width == 3);
    CHECK(img.height == 2);
    CHECK(img.grey == std::vector<std::uint8_t>{0, 1, 2, 253, 254, 255});
}

TEST_CASE("PNG files written by write_png read back exactly, colour as Rec.601 luma") {
    rays::test::TempDir dir;
    std::string error;
    const auto grey = ramp(9, 4, 1);
    REQUIRE(rays::io::write_png(dir.file("0.png"), 9, 4, 1, grey.data(), error));
    // Red, green, blue, grey 77, white, black, and so on across 9x4.
    std::vector<std::uint8_t> rgb(9 * 4 * 3, 0);
    const std::uint8_t colours[6][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {77, 77, 77}, {255, 255, 255}, {10, 20, 30}};
    std::vector<std::uint8_t> expected(9 * 4, 0);
    const std::uint8_t luma[6] = {76, 150, 29, 77, 255, 18};  // round(0.299 R + 0.587 G + 0.114 B)
    for (int i = 0; i < 6; ++i) {
        for (int k = 0; k < 3; ++k) rgb[static_cast<std::size_t>(3 * i + k)] = colours[i][k];
        expected[static_cast<std::size_t>(i)] = luma[i];
    }
    REQUIRE(rays::io::write_png(dir.file("1.png"), 9, 4, 3, rgb.data(), error));

    auto opened = open_frames(dir.path().string());
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == grey);
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == expected);
    CHECK(opened.reader->next(img) == Status::End);
}

TEST_CASE("PNG grey+alpha, RGBA, palette, 1-bit and 16-bit become 8-bit luma, alpha ignored") {
    rays::test::TempDir grey_alpha;
    write_raw_png(grey_alpha.file("a.png"), 3, 1, PNG_COLOR_TYPE_GRAY_ALPHA, 8, {10, 0, 20, 128, 30, 255});
    CHECK(read_single(grey_alpha.path().string()).grey == std::vector<std::uint8_t>{10, 20, 30});

    rays::test::TempDir rgba;
    write_raw_png(rgba.file("a.png"), 2, 1, PNG_COLOR_TYPE_RGB_ALPHA, 8, {255, 0, 0, 0, 40, 40, 40, 255});
    CHECK(read_single(rgba.path().string()).grey == std::vector<std::uint8_t>{76, 40});

    rays::test::TempDir palette;
    write_raw_png(palette.file("a.png"), 4, 1, PNG_COLOR_TYPE_PALETTE, 8, {2, 1, 0, 2},
                  {{0, 0, 0}, {0, 255, 0}, {200, 200, 200}});
    CHECK(read_single(palette.path().string()).grey == std::vector<std::uint8_t>{200, 150, 0, 200});

    rays::test::TempDir one_bit;
    write_raw_png(one_bit.file("a.png"), 8, 1, PNG_COLOR_TYPE_GRAY, 1, {0b10110000});
    CHECK(read_single(one_bit.path().string()).grey == std::vector<std::uint8_t>{255, 0, 255, 255, 0, 0, 0, 0});

    rays::test::TempDir sixteen;  // big-endian samples 0, 128·257, 65535
    write_raw_png(sixteen.file("a.png"), 3, 1, PNG_COLOR_TYPE_GRAY, 16, {0, 0, 128, 128, 255, 255});
    CHECK(read_single(sixteen.path().string()).grey == std::vector<std::uint8_t>{0, 128, 255});

    rays::test::TempDir rgb16;  // pure red at 16 bits
    write_raw_png(rgb16.file("a.png"), 1, 1, PNG_COLOR_TYPE_RGB, 16, {255, 255, 0, 0, 0, 0});
    CHECK(read_single(rgb16.path().string()).grey == std::vector<std::uint8_t>{76});
}

TEST_CASE("a frame of another size is an Error naming the file") {
    rays::test::TempDir dir;
    std::string error;
    const auto a = ramp(8, 8, 0);
    const auto b = ramp(8, 6, 0);
    REQUIRE(rays::io::write_png(dir.file("a.png"), 8, 8, 1, a.data(), error));
    REQUIRE(rays::io::write_png(dir.file("b.png"), 8, 6, 1, b.data(), error));
    auto opened = open_frames(dir.path().string());
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(opened.reader->next(img) == Status::Error);
    CHECK_THAT(opened.reader->error(), Catch::Contains("b.png: size 8x6 differs from the first frame's 8x8"));
    CHECK(opened.reader->next(img) == Status::Error);
}

TEST_CASE("a broken image is an Error naming the file") {
    rays::test::TempDir dir;
    std::vector<int> samples(4, 7);
    dir.write("a.pgm", p5(2, 2, 255, samples));
    const std::string full = p5(2, 2, 255, samples);
    dir.write("b.pgm", full.substr(0, full.size() - 2));  // samples cut short
    dir.write("c.png", "\x89PNG\r\n\x1a\n garbage");
    auto opened = open_frames(dir.path().string());
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(opened.reader->next(img) == Status::Error);
    CHECK_THAT(opened.reader->error(), Catch::Contains("b.pgm: truncated or invalid PGM samples"));

    rays::test::TempDir bad_png;
    bad_png.write("c.png", "\x89PNG\r\n\x1a\n garbage");
    auto failed = open_frames(bad_png.path().string());
    CHECK_FALSE(failed.reader);
    CHECK_THAT(failed.error, Catch::Contains("c.png: "));
}

TEST_CASE("a folder without images cannot be opened") {
    rays::test::TempDir dir;
    dir.write("readme.txt", "nothing here");
    auto opened = open_frames(dir.path().string());
    CHECK_FALSE(opened.reader);
    CHECK_THAT(opened.error, Catch::Contains("no .pgm or .png files"));
}
