// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <vector>

#include "io/png_decoder.hpp"
#include "io/png_writer.hpp"
#include "support/temp_dir.hpp"

TEST_CASE("encode_png writes a PNG that decodes to the same pixels and matches write_png's file") {
    std::vector<std::uint8_t> grey(31 * 17);
    for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = static_cast<std::uint8_t>(i * 13);
    std::vector<std::uint8_t> encoded;
    REQUIRE(rays::io::encode_png(31, 17, 1, grey.data(), encoded));
    REQUIRE(encoded.size() > 8);
    const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    CHECK(std::equal(signature, signature + 8, encoded.begin()));

    rays::test::TempDir dir;
    std::string error;
    REQUIRE(rays::io::write_png(dir.file("g.png"), 31, 17, 1, grey.data(), error));
    std::ifstream file(dir.file("g.png"), std::ios::binary);
    const std::vector<std::uint8_t> on_disk{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    CHECK(on_disk == encoded);

    rays::io::PngDecoder decoder;
    rays::io::SourceImage img;
    REQUIRE(decoder.decode(dir.file("g.png"), img, error));
    CHECK(img.width == 31);
    CHECK(img.height == 17);
    CHECK(img.grey == grey);
}

TEST_CASE("encode_png refuses bad shapes and write_png reports unwritable paths") {
    const std::uint8_t px[12] = {};
    std::vector<std::uint8_t> encoded{1, 2, 3};
    CHECK_FALSE(rays::io::encode_png(2, 2, 2, px, encoded));
    CHECK(encoded.empty());
    CHECK_FALSE(rays::io::encode_png(0, 2, 1, px, encoded));
    CHECK(rays::io::encode_png(2, 2, 3, px, encoded));

    rays::test::TempDir dir;
    std::string error;
    CHECK_FALSE(rays::io::write_png(dir.file("missing/dir/x.png"), 2, 2, 1, px, error));
    CHECK_THAT(error, Catch::Contains("x.png: cannot create"));
}
