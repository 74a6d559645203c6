// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include <array>
#include <string>

#include "capture/mjpeg_decoder.hpp"
#include "capture/pixel_format.hpp"

using namespace rays::capture;

namespace {

FormatRequest request(const std::string& text) {
    FormatRequest out;
    std::string error;
    REQUIRE(parse_format_request(text, out, error));
    return out;
}

}  // namespace

TEST_CASE("auto prefers GREY, then YUYV, then MJPEG, whatever the device's order") {
    std::string error;
    const std::array all{V4L2_PIX_FMT_MJPEG, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_GREY};
    CHECK(choose_format(request("auto"), all, error) == V4L2_PIX_FMT_GREY);
    const std::array no_grey{V4L2_PIX_FMT_MJPEG, V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_YUYV};
    CHECK(choose_format(request("auto"), no_grey, error) == V4L2_PIX_FMT_YUYV);
    const std::array jpeg_only{V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_JPEG};
    CHECK(choose_format(request("auto"), jpeg_only, error) == V4L2_PIX_FMT_JPEG);
}

TEST_CASE("an explicit format is honoured over a preferred one") {
    std::string error;
    const std::array all{V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_MJPEG};
    CHECK(choose_format(request("mjpeg"), all, error) == V4L2_PIX_FMT_MJPEG);
    CHECK(choose_format(request("yuyv"), all, error) == V4L2_PIX_FMT_YUYV);
}

TEST_CASE("an unsupported format is an error naming what the device has") {
    std::string error;
    const std::array offered{V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_NV12};
    CHECK_FALSE(choose_format(request("mjpeg"), offered, error));
    CHECK(error == "the device does not offer MJPEG (it has: YUYV, NV12)");
    const std::array none_of_ours{V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_RGB24};
    CHECK_FALSE(choose_format(request("auto"), none_of_ours, error));
    CHECK(error == "the device offers none of GREY, YUYV, MJPEG (it has: NV12, RGB3)");
}

TEST_CASE("format words other than auto, grey, yuyv, mjpeg are refused") {
    FormatRequest out;
    std::string error;
    CHECK_FALSE(parse_format_request("GREY", out, error));
    CHECK(error == "format 'GREY' is not one of auto, grey, yuyv, mjpeg");
}

TEST_CASE("the JPEG scale is the largest reduction that keeps 128 decoded pixels each way") {
    CHECK(choose_jpeg_scale(640, 480) == 2);
    CHECK(choose_jpeg_scale(1280, 720) == 4);
    CHECK(choose_jpeg_scale(1920, 1080) == 8);
    CHECK(choose_jpeg_scale(512, 512) == 4);
    CHECK(choose_jpeg_scale(255, 4000) == 1);
    CHECK(choose_jpeg_scale(100, 100) == 1);
}
