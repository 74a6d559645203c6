// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <linux/videodev2.h>

#include "camera_rig.hpp"
#include "capture/video_device.hpp"
#include "support/emulator.hpp"
#include "support/skip.hpp"

using namespace rays::capture;
using rays::test::CameraRig;
using rays::test::check_driver_clean;
using rays::test::FakeDriverConfig;
using rays::test::options_for;

TEST_CASE("open negotiates the preferred format the device offers and streams") {
    CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_MJPEG, V4L2_PIX_FMT_YUYV}});
    rig.open_streaming();
    CHECK(rig.device.format_set() == V4L2_PIX_FMT_YUYV);
    CHECK(rig.camera.pixel_format() == PixelFormat::Yuyv);
    CHECK(rig.device.streaming());
    CHECK(rig.device.buffer_count() == 4);
    CHECK(rig.device.mapped() == 4);
    CHECK((rig.device.last_open_flags() & O_NONBLOCK) != 0);
    CHECK(rig.camera.status() == "streaming 640x480 YUYV 30 fps");
    check_driver_clean(rig.device);
}

TEST_CASE("an explicit format is used even when a preferred one is offered") {
    CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_GREY, V4L2_PIX_FMT_MJPEG}}, options_for("mjpeg"));
    rig.open_streaming();
    CHECK(rig.device.format_set() == V4L2_PIX_FMT_MJPEG);
    CHECK(rig.camera.status() == "streaming 640x480 MJPEG (scale 1/2) 30 fps");
}

TEST_CASE("an explicit format the device lacks fails to open, naming the formats it has") {
    CameraRig rig(FakeDriverConfig{.formats = {V4L2_PIX_FMT_YUYV, V4L2_PIX_FMT_NV12}}, options_for("grey"));
    CHECK(rig.camera.open() == OpenResult::Failed);
    CHECK(rig.camera.error() == "/dev/video0: the device does not offer GREY (it has: YUYV, NV12)");
    CHECK(rig.camera.status() == "error: /dev/video0: the device does not offer GREY (it has: YUYV, NV12)");
    CHECK_FALSE(rig.device.is_open());
    CHECK(rig.next() == CaptureResult::Error);
}

TEST_CASE("the size and rate the driver grants are taken") {
    CameraRig rig(FakeDriverConfig{.granted_width = 320, .granted_height = 240, .max_fps = 15});
    rig.open_streaming();
    CHECK(rig.camera.width() == 320);
    CHECK(rig.camera.height() == 240);
    CHECK(rig.camera.fps() == 15.0);
    CHECK(rig.device.fps_set() == 15);
    CHECK(rig.camera.mapping().scale_x == 2.5);
    CHECK(rig.camera.mapping().offset_x == 0.75);
    CHECK(rig.camera.mapping().scale_y == 1.875);
    CHECK(rig.camera.mapping().offset_y == 0.4375);
    CHECK(rig.camera.status() == "streaming 320x240 GREY 15 fps");
}

TEST_CASE("a driver without frame intervals keeps its rate, and the status leaves it out") {
    CameraRig rig(FakeDriverConfig{.frame_intervals = false});
    rig.open_streaming();
    CHECK(rig.camera.fps() == 0.0);
    CHECK(rig.camera.status() == "streaming 640x480 GREY");
}

TEST_CASE("a crop outside the granted frame fails to open") {
    auto options = options_for();
    options.crop = rays::io::Crop{200, 0, 300, 200};
    CameraRig rig(FakeDriverConfig{.granted_width = 320, .granted_height = 240}, options);
    CHECK(rig.camera.open() == OpenResult::Failed);
    CHECK(rig.camera.error() == "/dev/video0: crop 300x200+200+0 is not inside the 320x240 source frame");
    CHECK_FALSE(rig.device.is_open());
    CHECK(rig.device.mapped() == 0);
}

TEST_CASE("a node that is not a video capture device fails to open") {
    CameraRig rig(FakeDriverConfig{.device_caps = V4L2_CAP_META_CAPTURE | V4L2_CAP_STREAMING});
    CHECK(rig.camera.open() == OpenResult::Failed);
    CHECK(rig.camera.error() == "/dev/video0: 'Fake Camera' is not a video capture device");
}

TEST_CASE("a driver granting one buffer fails to open and leaves nothing mapped") {
    CameraRig rig(FakeDriverConfig{.max_buffers = 1});
    CHECK(rig.camera.open() == OpenResult::Failed);
    CHECK(rig.camera.error() == "/dev/video0: the driver granted 1 buffers, 2 are needed");
    CHECK(rig.device.mapped() == 0);
    check_driver_clean(rig.device);
}

TEST_CASE("out-of-range options fail before the device is touched") {
    auto options = options_for("rgb");
    CameraRig bad_format(FakeDriverConfig{}, options);
    CHECK(bad_format.camera.open() == OpenResult::Failed);
    CHECK(bad_format.camera.error() == "format 'rgb' is not one of auto, grey, yuyv, mjpeg");
    options = options_for();
    options.buffers = 1;
    CameraRig few_buffers(FakeDriverConfig{}, options);
    CHECK(few_buffers.camera.open() == OpenResult::Failed);
    CHECK(few_buffers.camera.error() == "buffers 1 is out of range 2..32");
    CHECK(few_buffers.device.open_attempts().empty());
}

TEST_CASE("an absent device is not a failure: next() keeps trying") {
    auto options = options_for();
    options.device = "/dev/video7";
    CameraRig rig(FakeDriverConfig{}, options);
    CHECK(rig.camera.open() == OpenResult::DeviceAbsent);
    CHECK(rig.camera.status() == "disconnected: /dev/video7: open: ENOENT, retry in 0.5 s");
    CHECK(rig.next() == CaptureResult::Reconnecting);
}

TEST_CASE("the camera is closed and unmapped when it goes away") {
    rays::test::FakeClock clock;
    rays::test::FakeVideoDevice device(clock);
    {
        V4l2Camera camera(options_for(), device, clock);
        REQUIRE(camera.open() == OpenResult::Streaming);
        REQUIRE(camera.open() == OpenResult::Streaming);  // a second open starts afresh
    }
    CHECK_FALSE(device.is_open());
    CHECK(device.mapped() == 0);
    for (const std::string& v : device.violations()) FAIL_CHECK(v);
}

TEST_CASE("through the real syscalls: a missing node is absent, /dev/null is no V4L2 device") {
    if (!rays::test::emulator_words().empty())
        rays::test::skip("under qemu-user the V4L2 ioctls are not translated (VIDIOC_QUERYCAP fails with ENOSYS), "
                         "so this would test the emulator, not the camera code");
    SystemVideoDevice system;
    rays::SteadyClock clock;
    auto options = options_for();
    options.device = "/dev/rays-no-such-video-node";
    V4l2Camera missing(options, system, clock);
    CHECK(missing.open() == OpenResult::DeviceAbsent);
    options.device = "/dev/null";
    V4l2Camera not_video(options, system, clock);
    CHECK(not_video.open() == OpenResult::Failed);
    CHECK(not_video.error() == "/dev/null: not a V4L2 device (VIDIOC_QUERYCAP: ENOTTY)");
}
