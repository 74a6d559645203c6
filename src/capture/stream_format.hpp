// SPDX-License-Identifier: Apache-2.0
// Format negotiation on an open V4L2 device: capabilities, the format to use, its size and rate.
#pragma once
#include <cstdint>
#include <string>

#include "capture/frame_converter.hpp"
#include "capture/pixel_format.hpp"
#include "capture/v4l2_options.hpp"
#include "capture/video_device.hpp"

namespace rays::capture {

struct StreamFormat {
    FrameLayout layout;       // as the driver set it
    std::uint32_t fourcc = 0;
    double fps = 0.0;         // 0 when the driver does not say
    std::string card;         // the device's name for itself
};

// QUERYCAP (video capture with streaming I/O), ENUM_FMT and choose_format, S_FMT, then S_PARM when
// the driver supports frame intervals. False with error on failure.
bool negotiate(VideoDevice& device, int fd, const V4l2Options& options, FormatRequest request, StreamFormat& out,
               DeviceError& error);

}  // namespace rays::capture
