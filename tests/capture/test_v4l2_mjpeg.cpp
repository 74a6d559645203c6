// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include <random>

#include "camera_rig.hpp"
#include "test_frames.hpp"

using namespace rays::capture;
using rays::io::Crop;
using rays::test::CameraRig;
using rays::test::check_driver_clean;
using rays::test::FakeDriverConfig;
using rays::test::Luma;
using rays::test::options_for;

namespace {

FakeDriverConfig mjpeg_driver(int width, int height) {
    return FakeDriverConfig{.formats = {V4L2_PIX_FMT_MJPEG}, .granted_width = width, .granted_height = height};
}

}  // namespace

TEST_CASE("MJPEG is decoded at the largest DCT reduction the frame allows and looks like the scene") {
    struct Case {
        int width, height, scale;
    };
    for (const Case c : {Case{640, 480, 2}, Case{1280, 720, 4}, Case{1920, 1080, 8}, Case{200, 150, 1}}) {
        CameraRig rig(mjpeg_driver(c.width, c.height));
        rig.open_streaming();
        CHECK(rig.camera.jpeg_scale_denom() == c.scale);
        CHECK(rig.camera.status() == "streaming " + std::to_string(c.width) + "x" + std::to_string(c.height) +
                                         " MJPEG (scale 1/" + std::to_string(c.scale) + ") 30 fps");
        const Luma luma = rays::test::draw_pattern(c.width, c.height);
        rig.device.push(rays::test::encode_jpeg(luma));
        REQUIRE(rig.next() == CaptureResult::Frame);
        INFO(c.width << "x" << c.height);
        CHECK(rays::test::mean_abs_diff(rig.frame, rays::test::area_scaled(luma)) < 0.75);
        check_driver_clean(rig.device);
    }
}

TEST_CASE("an MJPEG crop picks its scale from the crop and maps back to the pixels averaged") {
    auto options = options_for();
    options.crop = Crop{301, 207, 512, 512};
    CameraRig rig(mjpeg_driver(1920, 1080), options);
    rig.open_streaming();
    CHECK(rig.camera.jpeg_scale_denom() == 4);
    // Decoded pixels 75..203 (of 4×4 source pixels each) cover source columns 300..815.
    CHECK(rig.camera.mapping().scale_x == 516.0 / 128);
    CHECK(rig.camera.mapping().offset_x == 300 + (516.0 / 128 - 1) / 2);
    CHECK(rig.camera.mapping().offset_y == 204 + (516.0 / 128 - 1) / 2);
    const Luma luma = rays::test::draw_pattern(1920, 1080);
    rig.device.push(rays::test::encode_jpeg(luma));
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rays::test::mean_abs_diff(rig.frame, rays::test::area_scaled(luma, Crop{300, 204, 516, 516})) < 0.75);
}

TEST_CASE("colour MJPEG gives its Rec.601 luma") {
    CameraRig rig(mjpeg_driver(640, 480));
    rig.open_streaming();
    rig.device.push(rays::test::encode_rgb_jpeg(640, 480, [](int x, int) { return x < 320 ? 0xff0000u : 0x0000ffu; }));
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(std::abs(rig.frame.at(20, 64) - 76) <= 2);   // red: 0.299 · 255
    CHECK(std::abs(rig.frame.at(100, 64) - 29) <= 2);  // blue: 0.114 · 255
}

TEST_CASE("MJPEG frames without Huffman tables, as webcams send them, decode with the standard tables") {
    CameraRig rig(mjpeg_driver(640, 480));
    rig.open_streaming();
    const auto jpeg = rays::test::encode_jpeg(rays::test::draw_pattern(640, 480));
    const auto bare = rays::test::strip_huffman_tables(jpeg);
    REQUIRE(bare.size() < jpeg.size());
    rig.device.push(jpeg);
    REQUIRE(rig.next() == CaptureResult::Frame);
    const rays::GreyImage with_tables = rig.frame;
    rig.device.push(bare);
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.frame.px == with_tables.px);
}

TEST_CASE("corrupt MJPEG frames are skipped and counted, and the next good frame comes through") {
    CameraRig rig(mjpeg_driver(640, 480));
    rig.open_streaming();
    const Luma luma = rays::test::draw_pattern(640, 480);
    const auto good = rays::test::encode_jpeg(luma);
    rig.device.push(std::vector<std::uint8_t>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(good.size() / 3)));
    rig.device.push(std::vector<std::uint8_t>(5000, 0x42));
    rig.device.push(std::vector<std::uint8_t>{});
    rig.device.push(rays::test::encode_jpeg(rays::test::draw_pattern(320, 240)));
    rig.device.push(good);
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.info.corrupt == 4);
    CHECK(rig.info.sequence == 4);
    CHECK(rig.camera.corrupt() == 4);
    CHECK(std::string(rig.camera.last_corrupt()) == "JPEG frame size differs from the negotiated size");
    CHECK(rays::test::mean_abs_diff(rig.frame, rays::test::area_scaled(luma)) < 0.75);
    CHECK(rig.camera.status() == "streaming 640x480 MJPEG (scale 1/2) 30 fps, 4 corrupt");
    check_driver_clean(rig.device);
}

TEST_CASE("randomly damaged MJPEG frames never crash: each is a frame or a counted skip") {
    CameraRig rig(mjpeg_driver(320, 240));
    rig.open_streaming();
    const auto good = rays::test::encode_jpeg(rays::test::draw_pattern(320, 240), 80);
    std::mt19937 random(7);
    constexpr int kFrames = 300;
    for (int i = 0; i < kFrames; ++i) {
        auto damaged = good;
        const int flips = 1 + static_cast<int>(random() % 8);
        for (int f = 0; f < flips; ++f) damaged[random() % damaged.size()] = static_cast<std::uint8_t>(random());
        rig.device.push(damaged);
    }
    while (rig.next() == CaptureResult::Frame) {
    }
    CHECK(rig.camera.frames() + rig.camera.corrupt() == kFrames);
    CHECK(rig.camera.corrupt() > 0);
    check_driver_clean(rig.device);
}
