// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include <algorithm>

#include "camera_rig.hpp"
#include "test_frames.hpp"

using namespace rays::capture;
using namespace std::chrono_literals;
using rays::GreyImage;
using rays::TimePoint;
using rays::io::Crop;
using rays::test::CameraRig;
using rays::test::check_driver_clean;
using rays::test::FakeDriverConfig;
using rays::test::FakeFrame;
using rays::test::Luma;
using rays::test::options_for;

namespace {

V4l2Options cropped(std::string format, Crop crop) {
    auto options = options_for(std::move(format));
    options.crop = crop;
    return options;
}

}  // namespace

TEST_CASE("GREY frames with padded rows and a crop come out as the area scaler makes them") {
    const Crop crop{37, 11, 270, 199};
    CameraRig rig(FakeDriverConfig{.granted_width = 333, .granted_height = 250, .line_padding = 19},
                  cropped("auto", crop));
    rig.open_streaming();
    const Luma luma = rays::test::draw_pattern(333, 250);
    rig.device.push(rays::test::pack_grey(luma, 19));
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.frame.px == rays::test::area_scaled(luma, crop).px);
    check_driver_clean(rig.device);
}

TEST_CASE("YUYV frames give their luma, cropped and scaled, at an odd size") {
    const Crop crop{3, 5, 301, 233};
    CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_YUYV}, .granted_width = 333, .granted_height = 251,
                                   .line_padding = 6},
                  cropped("auto", crop));
    rig.open_streaming();
    const Luma luma = rays::test::draw_pattern(333, 251);
    rig.device.push(rays::test::pack_yuyv(luma, 6));
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.frame.px == rays::test::area_scaled(luma, crop).px);
    check_driver_clean(rig.device);
}

// A 256×256 crop of an odd-sized frame: left half 200, right half 40, everything outside it 0.
// Each processing pixel averages 2×2 source pixels, so the halves must come out exact and unmixed.
TEST_CASE("a crop of an odd-sized frame maps to exact pixel values", "[scaling]") {
    const Crop crop{37, 11, 256, 256};
    for (const char* format : {"grey", "yuyv"}) {
        CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_YUYV}, .granted_width = 331,
                                       .granted_height = 277},
                      cropped(format, crop));
        rig.open_streaming();
        const Luma luma(331, 277, [&](int x, int y) -> std::uint8_t {
            if (x < crop.x || y < crop.y || x >= crop.x + crop.w || y >= crop.y + crop.h) return 0;
            return x < crop.x + crop.w / 2 ? 200 : 40;
        });
        rig.device.push(std::string(format) == "grey" ? rays::test::pack_grey(luma) : rays::test::pack_yuyv(luma));
        REQUIRE(rig.next() == CaptureResult::Frame);
        int wrong = 0;
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) wrong += rig.frame.at(x, y) != (x < 64 ? 200 : 40);
        INFO(format);
        CHECK(wrong == 0);
        CHECK(rig.camera.mapping().scale_x == 2.0);
        CHECK(rig.camera.mapping().offset_x == 37.5);
        CHECK(rig.camera.mapping().offset_y == 11.5);
    }
}

TEST_CASE("kernel timestamps are kept, with where in the frame they were taken") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    rig.device.push(FakeFrame{data, 7, timeval{4321, 123456}, 0});
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.info.timestamp == TimePoint{4321s + 123456us});
    CHECK(rig.info.timestamp_source == TimestampSource::EndOfFrame);
    CHECK(rig.info.sequence == 7);
    CHECK(rig.info.first_of_stream);

    CameraRig soe(FakeDriverConfig{.timestamp_flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_SOE});
    soe.open_streaming();
    soe.device.push(FakeFrame{data, 0, timeval{55, 5}, 0});
    REQUIRE(soe.next() == CaptureResult::Frame);
    CHECK(soe.info.timestamp == TimePoint{55s + 5us});
    CHECK(soe.info.timestamp_source == TimestampSource::StartOfExposure);
}

TEST_CASE("without monotonic kernel timestamps the dequeue time is used, and the status says so") {
    CameraRig rig(FakeDriverConfig{.timestamp_flags = V4L2_BUF_FLAG_TIMESTAMP_UNKNOWN});
    rig.open_streaming();
    CHECK(rig.camera.status() == "streaming 640x480 GREY 30 fps");
    rig.clock.advance(250ms);
    rig.device.push(FakeFrame{rays::test::pack_grey(rays::test::draw_pattern(640, 480)), 0, timeval{1, 0}, 0});
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.info.timestamp == rig.clock.now());
    CHECK(rig.info.timestamp_source == TimestampSource::Dequeue);
    CHECK(rig.camera.status() == "streaming 640x480 GREY 30 fps, timestamps at dequeue");
}

TEST_CASE("gaps in the driver's sequence numbers are counted as dropped frames") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    for (std::uint32_t sequence : {10u, 11u, 14u, 15u, 25u}) rig.device.push(FakeFrame{data, sequence, {}, 0});
    std::vector<std::uint32_t> dropped;
    while (rig.next() == CaptureResult::Frame) dropped.push_back(rig.info.dropped);
    CHECK(dropped == std::vector<std::uint32_t>{0, 0, 2, 0, 9});
    CHECK(rig.camera.drops() == 11);
    CHECK(rig.camera.frames() == 5);
    CHECK(rig.camera.status() == "streaming 640x480 GREY 30 fps, 11 dropped");
}

TEST_CASE("a sequence counter that wraps is not a drop, and one that restarts is not four billion drops") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    for (std::uint32_t sequence : {0xfffffffeu, 0xffffffffu, 0u, 2u, 1u}) rig.device.push(FakeFrame{data, sequence, {}, 0});
    while (rig.next() == CaptureResult::Frame) {
    }
    CHECK(rig.camera.drops() == 1);
}

TEST_CASE("every buffer cycles back to the driver over many frames") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    for (int i = 0; i < 1000; ++i) {
        rig.device.push(data);
        REQUIRE(rig.next() == CaptureResult::Frame);
        REQUIRE(rig.device.held_by_camera() == 0);
    }
    CHECK(rig.device.dequeues_per_buffer() == std::vector<int>{250, 250, 250, 250});
    check_driver_clean(rig.device);
}

TEST_CASE("frames that come in a burst are taken one per call, in order") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    for (int i = 0; i < 3; ++i) rig.device.push(data);
    for (std::uint32_t expected = 0; expected < 3; ++expected) {
        REQUIRE(rig.next() == CaptureResult::Frame);
        CHECK(rig.info.sequence == expected);
    }
    CHECK(rig.next() == CaptureResult::Timeout);
}

TEST_CASE("no frame within the timeout: Timeout after waiting that long") {
    CameraRig rig;
    rig.open_streaming();
    const TimePoint before = rig.clock.now();
    CHECK(rig.next(40ms) == CaptureResult::Timeout);
    CHECK(rig.clock.now() - before == 40ms);
    CHECK(rig.camera.status() == "streaming 640x480 GREY 30 fps");
}

TEST_CASE("buffers the driver flags as damaged, and short raw frames, are skipped and counted") {
    CameraRig rig;
    rig.open_streaming();
    const auto data = rays::test::pack_grey(rays::test::draw_pattern(640, 480));
    rig.device.push(FakeFrame{data, {}, {}, V4L2_BUF_FLAG_ERROR});
    rig.device.push(std::vector<std::uint8_t>(data.begin(), data.begin() + 1000));
    rig.device.push(data);
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK(rig.info.sequence == 2);
    CHECK(rig.info.corrupt == 2);
    CHECK(rig.info.dropped == 0);
    CHECK(rig.camera.corrupt() == 2);
    CHECK(std::string(rig.camera.last_corrupt()) == "short frame");
    CHECK(rig.camera.status() == "streaming 640x480 GREY 30 fps, 2 corrupt");
    check_driver_clean(rig.device);
}
