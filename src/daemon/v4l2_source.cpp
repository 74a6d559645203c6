// SPDX-License-Identifier: Apache-2.0
#include "daemon/v4l2_source.hpp"

namespace rays::daemon {
namespace {

capture::V4l2Options options_of(const CameraSettings& settings) {
    capture::V4l2Options options;
    options.device = settings.device;
    options.width = settings.width;
    options.height = settings.height;
    options.fps = settings.fps;
    options.format = settings.format;
    options.crop = {settings.crop_x, settings.crop_y, settings.crop_w, settings.crop_h};
    return options;
}

}  // namespace

V4l2Source::V4l2Source(const CameraSettings& settings, const Clock& clock, std::unique_ptr<capture::VideoDevice> device)
    : device_(std::move(device)), camera_(options_of(settings), *device_, clock) {}

std::unique_ptr<V4l2Source> V4l2Source::open(const CameraSettings& settings, const Clock& clock, std::string& error,
                                             std::unique_ptr<capture::VideoDevice> device) {
    if (!device) device = std::make_unique<capture::SystemVideoDevice>();
    std::unique_ptr<V4l2Source> source(new V4l2Source(settings, clock, std::move(device)));
    if (source->camera_.open() != capture::OpenResult::Streaming) {
        error = source->camera_.error().empty() ? settings.device + ": not present" : source->camera_.error();
        return nullptr;
    }
    return source;
}

FrameSource::Result V4l2Source::next(CapturedFrame& out, std::chrono::milliseconds timeout) {
    switch (camera_.next(out.image, out.chroma, info_, timeout)) {
    case capture::CaptureResult::Frame:
        out.index = delivered_++;
        out.stamp = info_.timestamp;
        return Result::Frame;
    case capture::CaptureResult::Timeout:
    case capture::CaptureResult::Reconnecting: return Result::Timeout;
    case capture::CaptureResult::Disconnected: return Result::Disconnected;
    case capture::CaptureResult::Error: return Result::Error;
    }
    return Result::Error;
}

}  // namespace rays::daemon
