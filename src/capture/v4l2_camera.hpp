// SPDX-License-Identifier: Apache-2.0
// A V4L2 camera as a frame source: mmap streaming of GREY, YUYV or MJPEG at whatever size the driver
// grants, cropped and area-averaged to 128×128, with the kernel's capture timestamps. When the device
// goes away the camera says so once, then reopens it with backoff and negotiates the format afresh.
//
// Runs on the capture thread: next() blocks up to its timeout, and MJPEG decoding allocates inside
// libjpeg-turbo. Everything else is sized when a stream opens. Not thread-safe.
#pragma once
#include <linux/videodev2.h>

#include <chrono>
#include <cstdint>
#include <string>

#include "capture/frame_converter.hpp"
#include "capture/mapped_buffers.hpp"
#include "capture/pixel_format.hpp"
#include "capture/stream_format.hpp"
#include "capture/v4l2_options.hpp"
#include "capture/video_device.hpp"
#include "core/clock.hpp"
#include "core/image.hpp"

namespace rays::capture {

enum class OpenResult {
    Streaming,     // frames can be read
    DeviceAbsent,  // the device is not there (yet); next() keeps trying to open it
    Failed,        // options or device unusable; error() says why, next() returns Error
};

enum class CaptureResult {
    Frame,         // out and info hold a new frame
    Timeout,       // no frame within the timeout (or a signal interrupted the wait)
    Disconnected,  // the device just went away (returned once): stop what the frames steer
    Reconnecting,  // still away; the camera retries with backoff
    Error,         // never opened, or opening failed for good
};

enum class TimestampSource {
    EndOfFrame,       // kernel monotonic time when the frame was complete
    StartOfExposure,  // kernel monotonic time when exposure began (e.g. UVC)
    Dequeue,          // the driver gave no monotonic time: the clock's time at dequeue
};

struct FrameInfo {
    TimePoint timestamp{};
    TimestampSource timestamp_source = TimestampSource::Dequeue;
    std::uint32_t sequence = 0;  // the driver's frame counter
    std::uint32_t dropped = 0;   // frames the driver lost just before this one (gap in sequence)
    std::uint32_t corrupt = 0;   // corrupt frames skipped since the previous delivered frame
    bool first_of_stream = false;  // first frame after an open: size and mapping may have changed
};

class V4l2Camera {
public:
    static constexpr std::chrono::milliseconds kFirstRetry{500};
    static constexpr std::chrono::milliseconds kLongestRetry{8000};

    V4l2Camera(V4l2Options options, VideoDevice& device, const Clock& clock);
    ~V4l2Camera();
    V4l2Camera(const V4l2Camera&) = delete;
    V4l2Camera& operator=(const V4l2Camera&) = delete;

    // Opens the device, negotiates the format and starts streaming. Reopens when already open.
    OpenResult open();

    // Waits up to timeout for the next frame and scales it into out (the luma) and chroma (present for
    // YUYV and colour MJPEG). Corrupt frames are skipped and counted. While the device is away, waits
    // for and makes the next reopen attempt.
    CaptureResult next(GreyImage& out, Chroma& chroma, FrameInfo& info, std::chrono::milliseconds timeout);

    // One line, e.g. "streaming 640x480 MJPEG (scale 1/2) 30 fps" or
    // "disconnected: /dev/video0: VIDIOC_DQBUF: ENODEV, retry in 2.0 s".
    std::string status() const;
    // Why the last open or stream failed; empty while streaming.
    const std::string& error() const { return error_; }
    // Why the last corrupt frame was skipped.
    const char* last_corrupt() const { return last_corrupt_; }

    // The stream as last negotiated.
    int width() const { return format_.layout.width; }
    int height() const { return format_.layout.height; }
    PixelFormat pixel_format() const { return format_.layout.format; }
    double fps() const { return format_.fps; }  // 0 when the driver does not say
    int jpeg_scale_denom() const { return converter_.jpeg_scale_denom(); }
    const SourceMapping& mapping() const { return converter_.mapping(); }

    std::uint64_t frames() const { return frames_; }
    std::uint64_t drops() const { return drops_; }
    std::uint64_t corrupt() const { return corrupt_; }
    std::uint64_t reconnects() const { return reconnects_; }

private:
    enum class State { Closed, Streaming, Lost, Failed };

    bool open_stream(DeviceError& error);
    void release();
    CaptureResult lose(const DeviceError& reason);
    void schedule_retry(std::chrono::milliseconds delay);
    bool reopen(TimePoint deadline);
    bool take_frame(const v4l2_buffer& buffer, GreyImage& out, Chroma& chroma, FrameInfo& info);
    void count_sequence(std::uint32_t sequence);
    int milliseconds_until(TimePoint deadline) const;

    V4l2Options options_;
    VideoDevice& device_;
    const Clock& clock_;
    FormatRequest request_;

    State state_ = State::Closed;
    int fd_ = -1;
    bool streaming_ = false;
    StreamFormat format_;
    FrameConverter converter_;
    MappedBuffers buffers_;
    std::string error_;

    std::chrono::milliseconds retry_delay_ = kFirstRetry;
    TimePoint retry_at_{};

    bool have_sequence_ = false;
    std::uint32_t last_sequence_ = 0;
    std::uint32_t dropped_since_frame_ = 0;
    std::uint32_t corrupt_since_frame_ = 0;
    bool first_of_stream_ = false;
    TimestampSource last_timestamp_source_ = TimestampSource::EndOfFrame;
    char last_corrupt_[128] = {};

    std::uint64_t frames_ = 0;
    std::uint64_t drops_ = 0;
    std::uint64_t corrupt_ = 0;
    std::uint64_t reconnects_ = 0;
};

}  // namespace rays::capture
