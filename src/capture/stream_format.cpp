// SPDX-License-Identifier: Apache-2.0
#include "capture/stream_format.hpp"

#include <linux/videodev2.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace rays::capture {
namespace {

bool check_capabilities(VideoDevice& device, int fd, StreamFormat& out, DeviceError& error) {
    v4l2_capability cap{};
    if (ioctl_retrying(device, fd, VIDIOC_QUERYCAP, &cap) == -1) {
        error = call_failed("VIDIOC_QUERYCAP");
        if (error.code == ENOTTY) error.message = "not a V4L2 device (VIDIOC_QUERYCAP: ENOTTY)";
        return false;
    }
    out.card.assign(reinterpret_cast<const char*>(cap.card), strnlen(reinterpret_cast<const char*>(cap.card), sizeof cap.card));
    const std::uint32_t caps = (cap.capabilities & V4L2_CAP_DEVICE_CAPS) != 0 ? cap.device_caps : cap.capabilities;
    if ((caps & V4L2_CAP_VIDEO_CAPTURE) == 0) error.message = "'" + out.card + "' is not a video capture device";
    else if ((caps & V4L2_CAP_STREAMING) == 0) error.message = "'" + out.card + "' has no streaming I/O";
    else return true;
    return false;
}

bool offered_formats(VideoDevice& device, int fd, std::vector<std::uint32_t>& out, DeviceError& error) {
    for (std::uint32_t index = 0;; ++index) {
        v4l2_fmtdesc desc{};
        desc.index = index;
        desc.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        if (ioctl_retrying(device, fd, VIDIOC_ENUM_FMT, &desc) == -1) {
            if (errno == EINVAL) return true;  // past the last one
            error = call_failed("VIDIOC_ENUM_FMT");
            return false;
        }
        out.push_back(desc.pixelformat);
    }
}

bool set_format(VideoDevice& device, int fd, const V4l2Options& options, std::uint32_t fourcc, StreamFormat& out,
                DeviceError& error) {
    v4l2_format format{};
    format.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    format.fmt.pix.width = static_cast<std::uint32_t>(options.width);
    format.fmt.pix.height = static_cast<std::uint32_t>(options.height);
    format.fmt.pix.pixelformat = fourcc;
    format.fmt.pix.field = V4L2_FIELD_ANY;
    if (ioctl_retrying(device, fd, VIDIOC_S_FMT, &format) == -1) {
        error = call_failed("VIDIOC_S_FMT " + fourcc_text(fourcc));
        return false;
    }
    const v4l2_pix_format& pix = format.fmt.pix;
    if (pix.pixelformat != fourcc) {
        error.message = "asked for " + fourcc_text(fourcc) + ", the driver set " + fourcc_text(pix.pixelformat);
        return false;
    }
    if (pix.width < 1 || pix.height < 1 || pix.width > 16384 || pix.height > 16384) {
        error.message = "the driver set a frame size of " + std::to_string(pix.width) + "x" + std::to_string(pix.height);
        return false;
    }
    out.fourcc = fourcc;
    out.layout.format = *format_of(fourcc);
    out.layout.width = static_cast<int>(pix.width);
    out.layout.height = static_cast<int>(pix.height);
    const std::uint32_t min_pitch = pix.width * (out.layout.format == PixelFormat::Yuyv ? 2u : 1u);
    out.layout.bytes_per_line = static_cast<int>(pix.bytesperline >= min_pitch ? pix.bytesperline : min_pitch);
    return true;
}

// A driver without frame interval support keeps its own rate; that is not an error.
void set_rate(VideoDevice& device, int fd, int fps, StreamFormat& out) {
    v4l2_streamparm parm{};
    parm.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (ioctl_retrying(device, fd, VIDIOC_G_PARM, &parm) == -1) return;
    if (fps > 0 && (parm.parm.capture.capability & V4L2_CAP_TIMEPERFRAME) != 0) {
        parm.parm.capture.timeperframe = v4l2_fract{1, static_cast<std::uint32_t>(fps)};
        if (ioctl_retrying(device, fd, VIDIOC_S_PARM, &parm) == -1) return;
    }
    const v4l2_fract interval = parm.parm.capture.timeperframe;
    if (interval.numerator > 0 && interval.denominator > 0)
        out.fps = static_cast<double>(interval.denominator) / interval.numerator;
}

}  // namespace

bool negotiate(VideoDevice& device, int fd, const V4l2Options& options, FormatRequest request, StreamFormat& out,
               DeviceError& error) {
    out = StreamFormat{};
    error = DeviceError{};
    if (!check_capabilities(device, fd, out, error)) return false;
    std::vector<std::uint32_t> offered;
    if (!offered_formats(device, fd, offered, error)) return false;
    const auto fourcc = choose_format(request, offered, error.message);
    if (!fourcc) return false;
    if (!set_format(device, fd, options, *fourcc, out, error)) return false;
    set_rate(device, fd, options.fps, out);
    return true;
}

}  // namespace rays::capture
