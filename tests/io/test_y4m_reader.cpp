// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "io/frame_reader.hpp"
#include "io/y4m_reader.hpp"
#include "io/y4m_writer.hpp"
#include "support/temp_dir.hpp"

using rays::io::FrameReader;
using rays::io::open_frames;
using rays::io::SourceImage;
using Status = FrameReader::Status;

namespace {

std::vector<std::uint8_t> pattern(int w, int h, int seed) {
    std::vector<std::uint8_t> px(static_cast<std::size_t>(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) px[static_cast<std::size_t>(y * w + x)] = static_cast<std::uint8_t>(x * 3 + y * 7 + seed * 11);
    return px;
}

std::string bytes(const std::vector<std::uint8_t>& v) { return std::string(v.begin(), v.end()); }

}  // namespace

TEST_CASE("Y4mWriter output reads back exactly, frame by frame") {
    rays::test::TempDir dir;
    const std::string path = dir.file("out.y4m");
    rays::io::Y4mWriter writer;
    REQUIRE(writer.open(path, 128, 128, 25, 1));
    for (int f = 0; f < 3; ++f) REQUIRE(writer.write(pattern(128, 128, f).data()));
    CHECK(writer.frames_written() == 3);
    REQUIRE(writer.close());

    std::FILE* raw = std::fopen(path.c_str(), "rb");
    REQUIRE(raw != nullptr);
    char header[64] = {};
    REQUIRE(std::fgets(header, sizeof header, raw) != nullptr);
    std::fclose(raw);
    CHECK(std::string(header) == "YUV4MPEG2 W128 H128 F25:1 Ip A1:1 Cmono\n");

    auto opened = open_frames(path);
    REQUIRE(opened.reader);
    FrameReader& reader = *opened.reader;
    CHECK(reader.width() == 128);
    CHECK(reader.height() == 128);
    CHECK(reader.fps() == 25.0);
    SourceImage img;
    for (int f = 0; f < 3; ++f) {
        REQUIRE(reader.next(img) == Status::Frame);
        CHECK(img.width == 128);
        CHECK(img.height == 128);
        CHECK(img.grey == pattern(128, 128, f));
    }
    CHECK(reader.next(img) == Status::End);
    CHECK(reader.next(img) == Status::End);
    CHECK(reader.error().empty());
}

TEST_CASE("Y4mWriter refuses bad parameters and closed streams") {
    rays::test::TempDir dir;
    rays::io::Y4mWriter writer;
    CHECK_FALSE(writer.open(dir.file("a.y4m"), 0, 128, 25, 1));
    CHECK_THAT(writer.error(), Catch::Contains("bad stream parameters"));
    CHECK_FALSE(writer.open(dir.file("no/such/dir/a.y4m"), 128, 128, 25, 1));
    CHECK_THAT(writer.error(), Catch::Contains("cannot create"));
    const std::uint8_t px[4] = {};
    CHECK_FALSE(writer.write(px));
    CHECK_THAT(writer.error(), Catch::Contains("closed"));
}

TEST_CASE("odd-sized 4:2:0 written by hand: luma and chroma exact, FRAME parameters ignored") {
    rays::test::TempDir dir;
    // 5x3 luma; chroma planes are ceil(5/2) x ceil(3/2) = 3x2 each, filled with values luma never has.
    const std::string chroma(12, static_cast<char>(0xAB));
    const auto y0 = pattern(5, 3, 0);
    const auto y1 = pattern(5, 3, 1);
    const std::string path =
        dir.write("odd.y4m", "YUV4MPEG2 W5 H3 F30000:1001 It A1:1 C420jpeg XYSCSS=420JPEG XCOLORRANGE=LIMITED\n"
                             "FRAME\n" + bytes(y0) + chroma + "FRAME Ip XFOO=1\n" + bytes(y1) + chroma);
    auto opened = open_frames(path);
    REQUIRE(opened.reader);
    CHECK(opened.reader->fps() == Approx(29.97).epsilon(1e-4));
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == y0);
    CHECK(img.chroma_width == 3);
    CHECK(img.chroma_height == 2);
    CHECK(img.u == std::vector<std::uint8_t>(6, 0xAB));
    CHECK(img.v == std::vector<std::uint8_t>(6, 0xAB));
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == y1);
    CHECK(opened.reader->next(img) == Status::End);
}

TEST_CASE("every supported colour space reads exactly its chroma planes (and skips alpha)") {
    struct Case {
        const char* colour;
        std::size_t chroma;  // bytes after the luma, for 5x3
        int chroma_w, chroma_h;
    };
    const Case cases[] = {{"", 12, 3, 2},   {"C420", 12, 3, 2}, {"C420mpeg2", 12, 3, 2}, {"C411", 12, 2, 3},
                          {"C422", 18, 3, 3}, {"C444", 30, 5, 3}, {"C444alpha", 45, 5, 3}, {"Cmono", 0, 0, 0}};
    rays::test::TempDir dir;
    for (const Case& c : cases) {
        INFO(c.colour);
        std::string stream = std::string("YUV4MPEG2 W5 H3 F25:1 ") + c.colour + "\n";
        for (int f = 0; f < 3; ++f) stream += "FRAME\n" + bytes(pattern(5, 3, f)) + std::string(c.chroma, '\x80');
        auto opened = open_frames(dir.write("c.y4m", stream));
        REQUIRE(opened.reader);
        SourceImage img;
        CHECK(opened.reader->chroma_width() == c.chroma_w);
        CHECK(opened.reader->chroma_height() == c.chroma_h);
        for (int f = 0; f < 3; ++f) {
            REQUIRE(opened.reader->next(img) == Status::Frame);
            CHECK(img.grey == pattern(5, 3, f));
            CHECK(img.has_chroma() == (c.chroma_w > 0));
            CHECK(img.u.size() == static_cast<std::size_t>(c.chroma_w * c.chroma_h));
        }
        CHECK(opened.reader->next(img) == Status::End);
    }
}

TEST_CASE("mono16 keeps the high byte of little-endian samples") {
    rays::test::TempDir dir;
    const std::uint16_t samples[6] = {0x0000, 0x00FF, 0x0100, 0x7F80, 0xFF00, 0xFFFF};
    std::string frame;
    for (std::uint16_t s : samples) frame += {static_cast<char>(s & 0xFF), static_cast<char>(s >> 8)};
    auto opened = open_frames(dir.write("m16.y4m", "YUV4MPEG2 W3 H2 F25:1 Cmono16\nFRAME\n" + frame));
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == std::vector<std::uint8_t>{0x00, 0x00, 0x01, 0x7F, 0xFF, 0xFF});
    CHECK(opened.reader->next(img) == Status::End);
}

TEST_CASE("a truncated frame is an Error saying how many bytes arrived, and stays an Error") {
    rays::test::TempDir dir;
    const std::string header = "YUV4MPEG2 W4 H4 F25:1 C420jpeg\n";  // 16 luma + 8 chroma bytes
    const std::string full = "FRAME\n" + std::string(24, '\x10');
    auto opened = open_frames(dir.write("t.y4m", header + full + "FRAME\n" + std::string(10, '\x20')));
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(opened.reader->next(img) == Status::Error);
    CHECK_THAT(opened.reader->error(), Catch::Contains("truncated frame 1: expected 24 bytes, got 10"));
    CHECK_THAT(opened.reader->error(), Catch::Contains("t.y4m"));
    CHECK(opened.reader->next(img) == Status::Error);

    // Luma complete, chroma cut short.
    auto cut_chroma = open_frames(dir.write("c.y4m", header + "FRAME\n" + std::string(20, '\x10')));
    REQUIRE(cut_chroma.reader);
    CHECK(cut_chroma.reader->next(img) == Status::Error);
    CHECK_THAT(cut_chroma.reader->error(), Catch::Contains("truncated frame 0: expected 24 bytes, got 20"));

    // Stream cut inside the marker.
    auto cut_marker = open_frames(dir.write("m.y4m", header + full + "FRA"));
    REQUIRE(cut_marker.reader);
    REQUIRE(cut_marker.reader->next(img) == Status::Frame);
    CHECK(cut_marker.reader->next(img) == Status::Error);
    CHECK_THAT(cut_marker.reader->error(), Catch::Contains("truncated FRAME marker of frame 1"));
}

TEST_CASE("a bad FRAME marker is an Error") {
    rays::test::TempDir dir;
    const std::string header = "YUV4MPEG2 W2 H2 F25:1 Cmono\n";
    for (const std::string marker : {"FRAMX\n", "FRAMEX\n", "frame\n"}) {
        INFO(marker);
        auto opened = open_frames(dir.write("b.y4m", header + "FRAME\n" + "abcd" + marker + "abcd"));
        REQUIRE(opened.reader);
        SourceImage img;
        REQUIRE(opened.reader->next(img) == Status::Frame);
        CHECK(opened.reader->next(img) == Status::Error);
        CHECK_THAT(opened.reader->error(), Catch::Contains("bad FRAME marker before frame 1"));
    }
}

TEST_CASE("opening fails with a one-line reason for a missing file, bad magic or a bad header") {
    rays::test::TempDir dir;
    auto missing = open_frames(dir.file("absent.y4m"));
    CHECK_FALSE(missing.reader);
    CHECK_THAT(missing.error, Catch::Contains("absent.y4m: no such file or directory"));

    auto magic = open_frames(dir.write("magic.y4m", "RIFF....AVI LIST\n"));
    CHECK_FALSE(magic.reader);
    CHECK_THAT(magic.error, Catch::Contains("magic.y4m: bad magic"));

    auto empty = open_frames(dir.write("empty.y4m", ""));
    CHECK_FALSE(empty.reader);
    CHECK_THAT(empty.error, Catch::Contains("empty stream"));

    auto huge = open_frames(dir.write("huge.y4m", "YUV4MPEG2 W100000 H8\n"));
    CHECK_FALSE(huge.reader);
    CHECK_THAT(huge.error, Catch::Contains("W100000 out of range"));

    auto no_newline = open_frames(dir.write("nl.y4m", "YUV4MPEG2 W8 H8"));
    CHECK_FALSE(no_newline.reader);
    CHECK_THAT(no_newline.error, Catch::Contains("not terminated"));
}

TEST_CASE("a header-only stream has no frames") {
    rays::test::TempDir dir;
    auto opened = open_frames(dir.write("h.y4m", "YUV4MPEG2 W8 H8 F25:1 Cmono\n"));
    REQUIRE(opened.reader);
    SourceImage img;
    CHECK(opened.reader->next(img) == Status::End);
}

TEST_CASE("reading frames after the first allocates nothing") {
    rays::test::TempDir dir;
    std::string stream = "YUV4MPEG2 W160 H120 F25:1 C420mpeg2 XCOLORRANGE=LIMITED\n";
    for (int f = 0; f < 5; ++f) stream += "FRAME\n" + bytes(pattern(160, 120, f)) + std::string(2 * 80 * 60, '\x80');
    auto opened = open_frames(dir.write("a.y4m", stream));
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    const std::size_t before = rays::test::allocations();
    for (int f = 1; f < 5; ++f) REQUIRE(opened.reader->next(img) == Status::Frame);
    CHECK(opened.reader->next(img) == Status::End);
    CHECK(rays::test::allocations() == before);
    CHECK(img.grey == pattern(160, 120, 4));
}

TEST_CASE("the path - reads YUV4MPEG2 from stdin") {
    rays::test::TempDir dir;
    const auto y = pattern(4, 2, 3);
    const std::string path = dir.write("in.y4m", "YUV4MPEG2 W4 H2 F25:1 Cmono\nFRAME\n" + bytes(y));
    const int saved = dup(STDIN_FILENO);
    REQUIRE(std::freopen(path.c_str(), "rb", stdin) != nullptr);
    auto opened = open_frames("-");
    REQUIRE(opened.reader);
    SourceImage img;
    CHECK(opened.reader->next(img) == Status::Frame);
    CHECK(img.grey == y);
    CHECK(opened.reader->next(img) == Status::End);
    opened.reader.reset();
    dup2(saved, STDIN_FILENO);
    std::clearerr(stdin);
    close(saved);
}
