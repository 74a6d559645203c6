// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "io/y4m_header.hpp"

using rays::io::parse_y4m_header;
using rays::io::Y4mColour;
using rays::io::Y4mHeader;

TEST_CASE("y4m header as ffmpeg writes it, with X extension parameters") {
    Y4mHeader h;
    std::string error;
    REQUIRE(parse_y4m_header("YUV4MPEG2 W160 H120 F26777:1000 Ip A1:1 C420mpeg2 XYSCSS=420MPEG2 XCOLORRANGE=LIMITED", h,
                             error));
    CHECK(h.width == 160);
    CHECK(h.height == 120);
    CHECK(h.fps() == Approx(26.777));
    CHECK(h.colour == Y4mColour::C420);
    CHECK(h.luma_bytes() == 160u * 120u);
    CHECK(h.chroma_bytes() == 2u * 80u * 60u);

    REQUIRE(parse_y4m_header("YUV4MPEG2 W192 H144 F10:1 Ip A0:0 Cmono XCOLORRANGE=FULL", h, error));
    CHECK(h.colour == Y4mColour::Mono);
    CHECK(h.chroma_bytes() == 0u);
    CHECK(h.fps() == 10.0);
}

TEST_CASE("y4m header defaults: 4:2:0 without C, unknown rate without F or with F0:0") {
    Y4mHeader h;
    std::string error;
    REQUIRE(parse_y4m_header("YUV4MPEG2 W5 H3", h, error));
    CHECK(h.colour == Y4mColour::C420);
    CHECK(h.chroma_bytes() == 2u * 3u * 2u);  // ceil(5/2) x ceil(3/2), twice
    CHECK(h.fps() == 0.0);
    REQUIRE(parse_y4m_header("YUV4MPEG2 W5 H3 F0:0", h, error));
    CHECK(h.fps() == 0.0);
}

TEST_CASE("y4m chroma sizes round up for odd frames") {
    struct Case {
        const char* colour;
        std::size_t chroma;
    };
    const Case cases[] = {{"C420jpeg", 2 * 3 * 2}, {"C420paldv", 12}, {"C411", 2 * 2 * 3}, {"C422", 2 * 3 * 3},
                          {"C444", 2 * 5 * 3},     {"C444alpha", 3 * 5 * 3}, {"Cmono", 0}};
    for (const Case& c : cases) {
        INFO(c.colour);
        Y4mHeader h;
        std::string error;
        REQUIRE(parse_y4m_header(std::string("YUV4MPEG2 W5 H3 ") + c.colour, h, error));
        CHECK(h.chroma_bytes() == c.chroma);
        CHECK(h.luma_bytes() == 15u);
    }
    Y4mHeader h;
    std::string error;
    REQUIRE(parse_y4m_header("YUV4MPEG2 W5 H3 Cmono16", h, error));
    CHECK(h.luma_bytes() == 30u);
}

TEST_CASE("y4m header errors are one-line reasons") {
    struct Case {
        const char* line;
        const char* reason;
    };
    const Case cases[] = {
        {"YUV4MPEG W8 H8", "bad magic"},
        {"YUV4MPEG2X W8 H8", "bad magic"},
        {"", "bad magic"},
        {"YUV4MPEG2 H8", "missing W"},
        {"YUV4MPEG2 W8", "missing H"},
        {"YUV4MPEG2 Wabc H8", "bad W value 'abc'"},
        {"YUV4MPEG2 W8 H+3", "bad H value '+3'"},
        {"YUV4MPEG2 W8 H3x", "bad H value '3x'"},
        {"YUV4MPEG2 W8 H-3", "H-3 out of range"},
        {"YUV4MPEG2 W9000 H8", "W9000 out of range 1..8192"},
        {"YUV4MPEG2 W8 H0", "H0 out of range"},
        {"YUV4MPEG2 W8 H8 F25", "bad frame rate F25"},
        {"YUV4MPEG2 W8 H8 C420p10", "unsupported colour space C420p10"},
    };
    for (const Case& c : cases) {
        INFO(c.line);
        Y4mHeader h;
        std::string error;
        CHECK_FALSE(parse_y4m_header(c.line, h, error));
        CHECK_THAT(error, Catch::Contains(c.reason));
        CHECK(error.find('\n') == std::string::npos);
    }
}
