// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <fstream>
#include <regex>
#include <sstream>

#include "io/area_scaler.hpp"
#include "io/frame_reader.hpp"
#include "support/skip.hpp"

using rays::io::FrameReader;
using rays::io::open_frames;
using rays::io::SourceImage;
using Status = FrameReader::Status;

namespace {

int count_frames(FrameReader& reader) {
    SourceImage img;
    int frames = 0;
    Status status;
    while ((status = reader.next(img)) == Status::Frame) ++frames;
    INFO(reader.error());
    CHECK(status == Status::End);
    return frames;
}

void check_sequence(const std::string& path, int w, int h, double fps, int frames) {
    INFO(path);
    auto opened = open_frames(path);
    INFO(opened.error);
    REQUIRE(opened.reader);
    CHECK(opened.reader->width() == w);
    CHECK(opened.reader->height() == h);
    CHECK(opened.reader->fps() == Approx(fps).epsilon(1e-4));
    CHECK(count_frames(*opened.reader) == frames);
}

}  // namespace

TEST_CASE("the recorded sequences open with their documented sizes and frame counts") {
    const auto data = rays::test::shared_dir_or_skip("the recorded sequences") / "data";
    check_sequence((data / "pedestrians-vtest.y4m").string(), 192, 144, 10.0, 795);
    check_sequence((data / "lab-cup.y4m").string(), 160, 120, 26.777, 217);
    check_sequence((data / "lab-box.y4m").string(), 160, 120, 29.97, 455);
    check_sequence((data / "lab-coin.y4m").string(), 184, 104, 30.0, 242);
}

TEST_CASE("the development scenes hold as many 128x128 frames as their meta.json says") {
    const auto devset = rays::test::shared_dir_or_skip("the development scenes") / "devset";
    int scenes = 0;
    for (const auto& scene : std::filesystem::directory_iterator(devset)) {
        if (!scene.is_directory()) continue;
        std::ifstream meta(scene.path() / "meta.json");
        std::stringstream text;
        text << meta.rdbuf();
        std::smatch m;
        const std::string json = text.str();
        REQUIRE(std::regex_search(json, m, std::regex("\"frames\"\\s*:\\s*(\\d+)")));
        check_sequence((scene.path() / "seq.y4m").string(), 128, 128, 25.0, std::stoi(m[1]));
        ++scenes;
    }
    CHECK(scenes >= 6);
}

TEST_CASE("a recorded frame scales to the processing frame keeping its mean brightness") {
    const auto data = rays::test::shared_dir_or_skip("the recorded sequences") / "data";
    auto opened = open_frames((data / "pedestrians-vtest.y4m").string());
    REQUIRE(opened.reader);
    SourceImage img;
    REQUIRE(opened.reader->next(img) == Status::Frame);
    std::string error;
    const auto scaler = rays::io::AreaScaler::make(img.width, img.height, {}, error);
    REQUIRE(scaler);
    rays::GreyImage out;
    scaler->scale(img.grey.data(), img.width, out);
    double source_mean = 0.0, scaled_mean = 0.0;
    for (auto v : img.grey) source_mean += v;
    for (auto v : out.px) scaled_mean += v;
    source_mean /= static_cast<double>(img.grey.size());
    scaled_mean /= static_cast<double>(out.px.size());
    CHECK(scaled_mean == Approx(source_mean).margin(0.5));
}
