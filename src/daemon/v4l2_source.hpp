// SPDX-License-Identifier: Apache-2.0
// A V4L2 camera as the daemon's frame source: the capture library's V4l2Camera on the real kernel
// interface, with the frame index counted here and the kernel's capture timestamps kept.
#pragma once
#include <memory>
#include <string>

#include "capture/v4l2_camera.hpp"
#include "capture/video_device.hpp"
#include "daemon/daemon_config.hpp"
#include "daemon/frame_source.hpp"

namespace rays::daemon {

class V4l2Source final : public FrameSource {
public:
    // Opens `device` (or the fake the tests pass) and starts streaming; null with `error` when the
    // camera is absent or unusable: the daemon does not report ready without its camera.
    static std::unique_ptr<V4l2Source> open(const CameraSettings& settings, const Clock& clock, std::string& error,
                                            std::unique_ptr<capture::VideoDevice> device = nullptr);

    Result next(CapturedFrame& out, std::chrono::milliseconds timeout) override;
    bool live() const override { return true; }
    std::string describe() const override { return camera_.status(); }

private:
    V4l2Source(const CameraSettings& settings, const Clock& clock, std::unique_ptr<capture::VideoDevice> device);

    std::unique_ptr<capture::VideoDevice> device_;
    capture::V4l2Camera camera_;
    capture::FrameInfo info_;
    long delivered_ = 0;
};

}  // namespace rays::daemon
