// SPDX-License-Identifier: Apache-2.0
// Colour through the replay path: a 4:2:0 YUV4MPEG2 stream's chroma reaches the frame at 64×64 over
// exactly the luma's area (crop and uneven scaling included), a mono one marks it absent, and
// scaling allocates nothing.
#include <catch2/catch.hpp>

#include <string>

#include "allocation_counter.hpp"
#include "io/frame_reader.hpp"
#include "io/frame_scaler.hpp"
#include "support/temp_dir.hpp"

using namespace rays;
using rays::io::FrameReader;

namespace {

// W×H 4:2:0 frames, luma 100; Cb/Cr (60, 200) left of luma x = split and (180, 70) right of it.
std::string sides_y4m(int w, int h, int split, int frames) {
    std::string out = "YUV4MPEG2 W" + std::to_string(w) + " H" + std::to_string(h) + " F25:1 C420jpeg\n";
    const int cw = (w + 1) / 2, ch = (h + 1) / 2;
    for (int f = 0; f < frames; ++f) {
        out += "FRAME\n" + std::string(static_cast<std::size_t>(w * h), static_cast<char>(100));
        for (const auto& [left, right] : {std::pair{60, 180}, std::pair{200, 70}})
            for (int y = 0; y < ch; ++y)
                for (int x = 0; x < cw; ++x) out += static_cast<char>(2 * x < split ? left : right);
    }
    return out;
}

struct Scaled {
    GreyImage luma;
    Chroma chroma;
};

Scaled read_first(const std::string& path, io::Crop crop) {
    auto opened = io::open_frames(path);
    REQUIRE(opened.reader);
    std::string error;
    const auto scaler = io::FrameScaler::make(opened.reader->width(), opened.reader->height(),
                                              opened.reader->chroma_width(), opened.reader->chroma_height(), crop, error);
    INFO(error);
    REQUIRE(scaler);
    io::SourceImage source;
    REQUIRE(opened.reader->next(source) == FrameReader::Status::Frame);
    Scaled out;
    scaler->scale(source, out.luma, out.chroma);
    return out;
}

}  // namespace

TEST_CASE("a 4:2:0 stream's chroma reaches the frame at 64x64 over the luma's area") {
    rays::test::TempDir dir;
    SECTION("256x128 onto 128x128: uneven scaling") {
        const Scaled s = read_first(dir.write("sides.y4m", sides_y4m(256, 128, 128, 1)), {});
        REQUIRE(s.chroma.present);
        CHECK(s.luma.at(5, 5) == 100);
        for (int y : {0, 63}) {
            CHECK(s.chroma.u_at(0, y) == 60);
            CHECK(s.chroma.v_at(31, y) == 200);
            CHECK(s.chroma.u_at(32, y) == 180);
            CHECK(s.chroma.v_at(63, y) == 70);
        }
    }
    SECTION("a crop whose left edge falls inside a chroma pixel") {
        // Luma x 97..224 (128 wide) onto 128: chroma column i covers luma [97 + 2i, 99 + 2i), the
        // split at 128 lies in column 15 (luma 127..129: half and half).
        const Scaled s = read_first(dir.write("crop.y4m", sides_y4m(256, 128, 128, 1)), io::Crop{97, 0, 128, 128});
        REQUIRE(s.chroma.present);
        CHECK(s.chroma.u_at(14, 3) == 60);
        CHECK(s.chroma.u_at(15, 3) == 120);  // (60 + 180) / 2
        CHECK(s.chroma.u_at(16, 3) == 180);
    }
}

TEST_CASE("a mono stream marks the chroma absent, scaling a colour frame allocates nothing") {
    rays::test::TempDir dir;
    const std::string mono = "YUV4MPEG2 W64 H64 F25:1 Cmono\nFRAME\n" + std::string(64 * 64, 'x');
    CHECK_FALSE(read_first(dir.write("mono.y4m", mono), {}).chroma.present);

    auto opened = io::open_frames(dir.write("sides.y4m", sides_y4m(320, 240, 100, 5)));
    REQUIRE(opened.reader);
    std::string error;
    const auto scaler = io::FrameScaler::make(320, 240, 160, 120, {}, error);
    REQUIRE(scaler);
    io::SourceImage source;
    Scaled out;
    REQUIRE(opened.reader->next(source) == FrameReader::Status::Frame);
    scaler->scale(source, out.luma, out.chroma);
    const std::size_t before = rays::test::allocations();
    int frames = 0;
    while (opened.reader->next(source) == FrameReader::Status::Frame) {
        scaler->scale(source, out.luma, out.chroma);
        ++frames;
    }
    CHECK(frames == 4);
    CHECK(rays::test::allocations() == before);
    CHECK(out.chroma.present);
}
