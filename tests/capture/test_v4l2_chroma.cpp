// SPDX-License-Identifier: Apache-2.0
// The chroma of captured frames through the ioctl-level seam: YUYV's Cb and Cr and a colour MJPEG's
// reach the frame at 64×64 over the crop's area; GREY delivers none.
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include "camera_rig.hpp"
#include "test_frames.hpp"

using namespace rays;
using namespace rays::capture;
using rays::test::CameraRig;
using rays::test::FakeDriverConfig;
using rays::test::options_for;

namespace {

// YUYV with a flat luma and Cb/Cr by which side of x = split a pixel pair lies.
std::vector<std::uint8_t> pack_yuyv_sides(int width, int height, int split, int padding) {
    const int pitch = 2 * width + padding;
    std::vector<std::uint8_t> out(static_cast<std::size_t>(pitch * height), 0);
    for (int y = 0; y < height; ++y)
        for (int pair = 0; pair < width / 2; ++pair) {
            std::uint8_t* p = &out[static_cast<std::size_t>(y * pitch + 4 * pair)];
            const bool left = 2 * pair < split;
            p[0] = p[2] = 100;
            p[1] = left ? 60 : 180;   // Cb
            p[3] = left ? 200 : 70;   // Cr
        }
    return out;
}

}  // namespace

TEST_CASE("YUYV chroma reaches the frame at 64x64 over the crop, exactly as the luma's area") {
    SECTION("the whole frame") {
        CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_YUYV}, .line_padding = 16}, options_for("yuyv", 256, 256));
        rig.open_streaming();
        rig.device.push(pack_yuyv_sides(256, 256, 128, 16));
        REQUIRE(rig.next() == CaptureResult::Frame);
        REQUIRE(rig.chroma.present);
        for (int y : {0, 31, 63}) {
            for (int x : {0, 31}) {
                CHECK(rig.chroma.u_at(x, y) == 60);
                CHECK(rig.chroma.v_at(x, y) == 200);
            }
            for (int x : {32, 63}) {
                CHECK(rig.chroma.u_at(x, y) == 180);
                CHECK(rig.chroma.v_at(x, y) == 70);
            }
        }
    }
    SECTION("an odd, uneven crop: the chroma follows the luma's area, half a chroma pixel in") {
        auto options = options_for("yuyv", 256, 256);
        options.crop = io::Crop{63, 0, 130, 256};  // 130 px wide onto 128, 256 tall onto 128
        CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_YUYV}}, options);
        rig.open_streaming();
        rig.device.push(pack_yuyv_sides(256, 256, 128, 0));
        REQUIRE(rig.next() == CaptureResult::Frame);
        REQUIRE(rig.chroma.present);
        // Chroma column i covers luma x in [63 + 130·i/64, 63 + 130·(i+1)/64): left of 128 up to i = 31,
        // i = 32 straddles 128 (from 128.0 to 130.03: right), right beyond.
        CHECK(rig.chroma.u_at(0, 10) == 60);
        CHECK(rig.chroma.u_at(31, 10) == 60);
        CHECK(rig.chroma.u_at(32, 10) == 180);
        CHECK(rig.chroma.v_at(63, 63) == 70);
    }
}

TEST_CASE("a colour MJPEG frame reaches the frame with its chroma, GREY with none") {
    {
        CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_MJPEG}});
        rig.open_streaming();
        // Red left of x = 320, blue right of it: Cb ≈ 85 / 255, Cr ≈ 255 / 107 in full-range BT.601.
        rig.device.push(rays::test::encode_rgb_jpeg(640, 480, [](int x, int) { return x < 320 ? 0xff0000u : 0x0000ffu; }));
        REQUIRE(rig.next() == CaptureResult::Frame);
        REQUIRE(rig.chroma.present);
        for (int y : {5, 60}) {
            CHECK(rig.chroma.u_at(10, y) == Approx(85).margin(8));
            CHECK(rig.chroma.v_at(10, y) == Approx(255).margin(8));
            CHECK(rig.chroma.u_at(50, y) == Approx(255).margin(8));
            CHECK(rig.chroma.v_at(50, y) == Approx(107).margin(8));
        }
        CHECK(rig.frame.at(10, 10) == Approx(76).margin(8));  // red's luma
    }
    {
        CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_GREY}});
        rig.open_streaming();
        rig.device.push(rays::test::pack_grey(rays::test::draw_pattern(640, 480)));
        REQUIRE(rig.next() == CaptureResult::Frame);
        CHECK_FALSE(rig.chroma.present);
    }
}
