// SPDX-License-Identifier: Apache-2.0
// What the camera asks the device for. The driver may grant another size or rate; the camera takes it.
#pragma once
#include <string>

#include "io/area_scaler.hpp"

namespace rays::capture {

struct V4l2Options {
    std::string device = "/dev/video0";
    int width = 640;
    int height = 480;
    int fps = 30;                  // 0: leave the driver's rate
    std::string format = "auto";   // auto | grey | yuyv | mjpeg
    io::Crop crop;                 // in pixels of the negotiated frame; w = 0: the whole frame
    int buffers = 4;               // mmap buffers to request, 2..32
};

}  // namespace rays::capture
