// SPDX-License-Identifier: Apache-2.0
// A camera on the fake driver with a fake clock, and the checks every test ends with.
#pragma once
#include <catch2/catch.hpp>

#include <chrono>
#include <string>

#include "capture/v4l2_camera.hpp"
#include "fake_clock.hpp"
#include "fake_video_device.hpp"

namespace Catch {
template <>
struct StringMaker<rays::capture::CaptureResult> {
    static std::string convert(rays::capture::CaptureResult r) {
        constexpr const char* names[] = {"Frame", "Timeout", "Disconnected", "Reconnecting", "Error"};
        return names[static_cast<int>(r)];
    }
};
template <>
struct StringMaker<rays::capture::OpenResult> {
    static std::string convert(rays::capture::OpenResult r) {
        constexpr const char* names[] = {"Streaming", "DeviceAbsent", "Failed"};
        return names[static_cast<int>(r)];
    }
};
}  // namespace Catch

namespace rays::test {

inline capture::V4l2Options options_for(std::string format = "auto", int width = 640, int height = 480) {
    capture::V4l2Options options;
    options.format = std::move(format);
    options.width = width;
    options.height = height;
    return options;
}

struct CameraRig {
    FakeClock clock;
    FakeVideoDevice device;
    capture::V4l2Camera camera;
    GreyImage frame;
    Chroma chroma;
    capture::FrameInfo info;

    explicit CameraRig(FakeDriverConfig config = {}, capture::V4l2Options options = options_for())
        : device(clock, std::move(config)), camera(std::move(options), device, clock) {}

    capture::CaptureResult next(std::chrono::milliseconds timeout = std::chrono::milliseconds{100}) {
        return camera.next(frame, chroma, info, timeout);
    }
    void open_streaming() {
        const capture::OpenResult opened = camera.open();
        INFO(camera.status());
        REQUIRE(opened == capture::OpenResult::Streaming);
    }
};

// The driver saw no misuse, and the camera holds no buffer between frames.
inline void check_driver_clean(const FakeVideoDevice& device) {
    for (const std::string& v : device.violations()) FAIL_CHECK(v);
    CHECK(device.held_by_camera() == 0);
}

}  // namespace rays::test
