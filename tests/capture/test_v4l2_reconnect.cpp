// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <linux/videodev2.h>

#include "camera_rig.hpp"
#include "test_frames.hpp"

using namespace rays::capture;
using namespace std::chrono_literals;
using rays::TimePoint;
using rays::test::CameraRig;
using rays::test::check_driver_clean;
using rays::test::FakeDriverConfig;

namespace {

std::vector<std::uint8_t> grey_frame() { return rays::test::pack_grey(rays::test::draw_pattern(640, 480)); }

// Streams one frame, then pulls the plug and takes the Disconnected.
void stream_then_unplug(CameraRig& rig) {
    rig.open_streaming();
    rig.device.push(grey_frame());
    REQUIRE(rig.next() == CaptureResult::Frame);
    rig.device.unplug();
    REQUIRE(rig.next() == CaptureResult::Disconnected);
}

}  // namespace

TEST_CASE("an unplug is reported once as Disconnected, with the buffers unmapped and the device closed") {
    CameraRig rig;
    stream_then_unplug(rig);
    CHECK_FALSE(rig.device.is_open());
    CHECK(rig.device.mapped() == 0);
    CHECK(rig.camera.error() == "/dev/video0: poll: POLLHUP");
    CHECK(rig.camera.status() == "disconnected: /dev/video0: poll: POLLHUP, retry in 0.5 s");
    CHECK(rig.next(100ms) == CaptureResult::Reconnecting);
    CHECK(rig.camera.status() == "disconnected: /dev/video0: poll: POLLHUP, retry in 0.4 s");
    check_driver_clean(rig.device);
}

TEST_CASE("reopening backs off 0.5, 1, 2, 4, 8, 8 s, waiting in next() rather than spinning") {
    CameraRig rig;
    stream_then_unplug(rig);
    const TimePoint lost = rig.clock.now();
    const std::size_t attempts_before = rig.device.open_attempts().size();
    while (rig.clock.now() - lost < 30s) {
        const TimePoint before = rig.clock.now();
        REQUIRE(rig.next(100ms) == CaptureResult::Reconnecting);
        REQUIRE(rig.clock.now() - before == 100ms);
    }
    std::vector<double> attempts;
    for (std::size_t i = attempts_before; i < rig.device.open_attempts().size(); ++i)
        attempts.push_back(std::chrono::duration<double>(rig.device.open_attempts()[i] - lost).count());
    CHECK(attempts == std::vector<double>{0.5, 1.5, 3.5, 7.5, 15.5, 23.5});
    CHECK(rig.camera.status() == "disconnected: /dev/video0: open: ENOENT, retry in 1.5 s");
    check_driver_clean(rig.device);
}

TEST_CASE("the device comes back with other formats: renegotiated, and frames flow again") {
    CameraRig rig;
    stream_then_unplug(rig);
    CHECK(rig.next(1s) == CaptureResult::Reconnecting);  // attempt at 0.5 s fails
    rig.device.replug(FakeDriverConfig{.formats = {V4L2_PIX_FMT_NV12, V4L2_PIX_FMT_MJPEG},
                                       .granted_width = 1280,
                                       .granted_height = 720});
    const rays::test::Luma luma = rays::test::draw_pattern(1280, 720);
    rig.device.push(rays::test::encode_jpeg(luma));
    REQUIRE(rig.next(1s) == CaptureResult::Frame);  // attempt at 1.5 s succeeds
    CHECK(rig.info.first_of_stream);
    CHECK(rig.info.sequence == 0);
    CHECK(rig.info.dropped == 0);
    CHECK(rig.camera.reconnects() == 1);
    CHECK(rig.camera.pixel_format() == PixelFormat::Mjpeg);
    CHECK(rig.camera.width() == 1280);
    CHECK(rig.camera.mapping().scale_x == 10.0);
    CHECK(rig.camera.status() == "streaming 1280x720 MJPEG (scale 1/4) 30 fps");
    CHECK(rig.camera.error().empty());
    CHECK(rays::test::mean_abs_diff(rig.frame, rays::test::area_scaled(luma)) < 0.75);

    rig.device.push(rays::test::encode_jpeg(luma));
    REQUIRE(rig.next() == CaptureResult::Frame);
    CHECK_FALSE(rig.info.first_of_stream);
    check_driver_clean(rig.device);
}

TEST_CASE("after a reconnect the backoff starts again at 0.5 s") {
    CameraRig rig;
    stream_then_unplug(rig);
    CHECK(rig.next(2s) == CaptureResult::Reconnecting);  // attempts at 0.5 and 1.5 s
    rig.device.replug(FakeDriverConfig{});
    CHECK(rig.next(3s) == CaptureResult::Timeout);       // reopened at 3.5 s
    rig.device.unplug();
    CHECK(rig.next() == CaptureResult::Disconnected);
    CHECK(rig.camera.status() == "disconnected: /dev/video0: poll: POLLHUP, retry in 0.5 s");
}

TEST_CASE("DQBUF or QBUF failing with ENODEV or EIO is a disconnect, and the same device is reopened") {
    for (const unsigned long request : {VIDIOC_DQBUF, VIDIOC_QBUF}) {
        for (const int error : {ENODEV, EIO}) {
            CameraRig rig;
            rig.open_streaming();
            rig.device.fail_next(request, error);
            rig.device.push(grey_frame());
            REQUIRE(rig.next() == CaptureResult::Disconnected);
            const std::string call = request == VIDIOC_DQBUF ? "VIDIOC_DQBUF" : "VIDIOC_QBUF";
            CHECK(rig.camera.error() == "/dev/video0: " + call + ": " + errno_name(error));
            CHECK_FALSE(rig.device.is_open());
            rig.device.push(grey_frame());
            REQUIRE(rig.next(1s) == CaptureResult::Frame);
            CHECK(rig.info.first_of_stream);
            CHECK(rig.camera.reconnects() == 1);
            check_driver_clean(rig.device);
        }
    }
}

TEST_CASE("a signal during the wait is a Timeout, poll failing otherwise is a disconnect") {
    CameraRig rig;
    rig.open_streaming();
    rig.device.fail_next_poll(EINTR);
    CHECK(rig.next() == CaptureResult::Timeout);
    rig.device.push(grey_frame());
    CHECK(rig.next() == CaptureResult::Frame);
    rig.device.fail_next_poll(ENOMEM);
    CHECK(rig.next() == CaptureResult::Disconnected);
    CHECK(rig.camera.error() == "/dev/video0: poll: ENOMEM");
    check_driver_clean(rig.device);
}

TEST_CASE("a device that comes back unusable is retried, with the reason in the status") {
    CameraRig rig;
    stream_then_unplug(rig);
    rig.device.replug(FakeDriverConfig{.formats = {V4L2_PIX_FMT_NV12}});
    CHECK(rig.next(1s) == CaptureResult::Reconnecting);
    CHECK_FALSE(rig.device.is_open());
    CHECK(rig.camera.status() ==
          "disconnected: /dev/video0: the device offers none of GREY, YUYV, MJPEG (it has: NV12), retry in 0.5 s");
    rig.device.replug(FakeDriverConfig{});
    rig.device.push(grey_frame());
    CHECK(rig.next(1s) == CaptureResult::Frame);
    check_driver_clean(rig.device);
}

TEST_CASE("a camera absent at start streams once it is plugged in") {
    CameraRig rig;
    rig.device.unplug();
    CHECK(rig.camera.open() == OpenResult::DeviceAbsent);
    CHECK(rig.next(300ms) == CaptureResult::Reconnecting);
    rig.device.replug(FakeDriverConfig{});
    rig.device.push(grey_frame());
    CHECK(rig.next(300ms) == CaptureResult::Frame);
    CHECK(rig.info.first_of_stream);
    check_driver_clean(rig.device);
}
