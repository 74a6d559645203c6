// SPDX-License-Identifier: Apache-2.0
// The frame path allocates nothing once streaming: no operator new per frame in GREY, YUYV or MJPEG,
// chroma included
// (libjpeg-turbo's own mallocs inside each decode are not operator new and are not counted here).
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include "allocation_counter.hpp"
#include "camera_rig.hpp"
#include "test_frames.hpp"

using namespace rays::capture;
using rays::test::CameraRig;
using rays::test::FakeDriverConfig;
using rays::test::options_for;

TEST_CASE("steady-state frames allocate nothing in the camera") {
    struct Case {
        const char* format;
        std::uint32_t fourcc;
    };
    for (const Case c : {Case{"grey", V4L2_PIX_FMT_GREY}, Case{"yuyv", V4L2_PIX_FMT_YUYV}, Case{"mjpeg", V4L2_PIX_FMT_MJPEG}}) {
        auto options = options_for(c.format);
        options.crop = rays::io::Crop{16, 8, 600, 400};
        CameraRig rig(FakeDriverConfig{.formats = {c.fourcc}, .line_padding = 32}, options);
        rig.open_streaming();
        const rays::test::Luma luma = rays::test::draw_pattern(640, 480);
        const auto data = c.fourcc == V4L2_PIX_FMT_GREY   ? rays::test::pack_grey(luma, 32)
                          : c.fourcc == V4L2_PIX_FMT_YUYV ? rays::test::pack_yuyv(luma, 32)
                                                          : rays::test::encode_jpeg(luma);
        constexpr int kFrames = 40;
        for (int i = 0; i < kFrames; ++i) rig.device.push(data);
        REQUIRE(rig.next() == CaptureResult::Frame);

        const std::size_t before = rays::test::allocations();
        int frames = 0;
        while (rig.next() == CaptureResult::Frame) ++frames;
        const std::size_t allocated = rays::test::allocations() - before;

        INFO(c.format);
        CHECK(frames == kFrames - 1);
        CHECK(allocated == 0);
        CHECK(rig.chroma.present == (c.fourcc != V4L2_PIX_FMT_GREY));  // YUYV and the (YCbCr) JPEG have colour
    }
}
