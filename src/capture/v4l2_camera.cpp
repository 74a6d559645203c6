// SPDX-License-Identifier: Apache-2.0
#include "capture/v4l2_camera.hpp"

#include <fcntl.h>
#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>

namespace rays::capture {
namespace {

bool device_absent(int code) { return code == ENOENT || code == ENODEV || code == ENXIO; }

std::string check_options(const V4l2Options& options, FormatRequest& request) {
    std::string error;
    if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
        return "frame size " + std::to_string(options.width) + "x" + std::to_string(options.height) + " is out of range";
    if (options.fps < 0 || options.fps > 1000) return "fps " + std::to_string(options.fps) + " is out of range 0..1000";
    if (options.buffers < 2 || options.buffers > 32)
        return "buffers " + std::to_string(options.buffers) + " is out of range 2..32";
    parse_format_request(options.format, request, error);
    return error;
}

TimePoint kernel_time(const timeval& time) {
    return TimePoint{std::chrono::duration_cast<MonoClock::duration>(std::chrono::seconds{time.tv_sec} +
                                                                     std::chrono::microseconds{time.tv_usec})};
}

}  // namespace

V4l2Camera::V4l2Camera(V4l2Options options, VideoDevice& device, const Clock& clock)
    : options_(std::move(options)), device_(device), clock_(clock) {}

V4l2Camera::~V4l2Camera() { release(); }

OpenResult V4l2Camera::open() {
    release();
    error_ = check_options(options_, request_);
    if (!error_.empty()) {
        state_ = State::Failed;
        return OpenResult::Failed;
    }
    DeviceError error;
    if (open_stream(error)) return OpenResult::Streaming;
    error_ = options_.device + ": " + error.message;
    if (!device_absent(error.code)) {
        state_ = State::Failed;
        return OpenResult::Failed;
    }
    state_ = State::Lost;
    schedule_retry(kFirstRetry);
    return OpenResult::DeviceAbsent;
}

bool V4l2Camera::open_stream(DeviceError& error) {
    fd_ = device_.open(options_.device.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (fd_ == -1) {
        error = call_failed("open");
        return false;
    }
    if (!negotiate(device_, fd_, options_, request_, format_, error) ||
        !converter_.configure(format_.layout, options_.crop, error.message) ||
        !buffers_.allocate(device_, fd_, options_.buffers, error)) {
        release();
        return false;
    }
    int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
    if (ioctl_retrying(device_, fd_, VIDIOC_STREAMON, &type) == -1) {
        error = call_failed("VIDIOC_STREAMON");
        release();
        return false;
    }
    streaming_ = true;
    state_ = State::Streaming;
    error_.clear();
    have_sequence_ = false;
    dropped_since_frame_ = 0;
    corrupt_since_frame_ = 0;
    first_of_stream_ = true;
    return true;
}

// Errors are ignored: after an unplug every call but munmap and close fails with ENODEV.
void V4l2Camera::release() {
    if (fd_ == -1) return;
    if (streaming_) {
        int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        ioctl_retrying(device_, fd_, VIDIOC_STREAMOFF, &type);
        streaming_ = false;
    }
    buffers_.release(device_);
    device_.close(fd_);
    fd_ = -1;
}

CaptureResult V4l2Camera::lose(const DeviceError& reason) {
    release();
    error_ = options_.device + ": " + reason.message;
    state_ = State::Lost;
    schedule_retry(kFirstRetry);
    return CaptureResult::Disconnected;
}

void V4l2Camera::schedule_retry(std::chrono::milliseconds delay) {
    retry_delay_ = delay;
    retry_at_ = clock_.now() + delay;
}

// Sleeps until the retry time or the deadline, whichever comes first, and tries when it is due.
bool V4l2Camera::reopen(TimePoint deadline) {
    for (;;) {
        if (clock_.now() >= retry_at_) {
            DeviceError error;
            if (open_stream(error)) {
                ++reconnects_;
                return true;
            }
            error_ = options_.device + ": " + error.message;
            schedule_retry(std::min(2 * retry_delay_, kLongestRetry));
        }
        const TimePoint now = clock_.now();
        if (now >= deadline) return false;
        device_.poll(-1, milliseconds_until(std::min(retry_at_, deadline)));
    }
}

int V4l2Camera::milliseconds_until(TimePoint deadline) const {
    const auto left = std::chrono::ceil<std::chrono::milliseconds>(deadline - clock_.now()).count();
    return static_cast<int>(std::clamp<decltype(left)>(left, 0, INT_MAX));
}

CaptureResult V4l2Camera::next(GreyImage& out, Chroma& chroma, FrameInfo& info, std::chrono::milliseconds timeout) {
    const TimePoint deadline = clock_.now() + timeout;
    if (state_ == State::Lost && !reopen(deadline)) return CaptureResult::Reconnecting;
    if (state_ != State::Streaming) return CaptureResult::Error;
    for (;;) {
        const int revents = device_.poll(fd_, milliseconds_until(deadline));
        if (revents == 0) return CaptureResult::Timeout;
        if (revents == -1) return errno == EINTR ? CaptureResult::Timeout : lose(call_failed("poll"));
        if ((revents & (POLLERR | POLLHUP)) != 0)
            return lose(DeviceError{0, (revents & POLLHUP) != 0 ? "poll: POLLHUP" : "poll: POLLERR"});
        v4l2_buffer buffer{};
        buffer.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
        buffer.memory = V4L2_MEMORY_MMAP;
        if (ioctl_retrying(device_, fd_, VIDIOC_DQBUF, &buffer) == -1) {
            if (errno != EAGAIN) return lose(call_failed("VIDIOC_DQBUF"));
            if (clock_.now() >= deadline) return CaptureResult::Timeout;
            continue;
        }
        const bool delivered = take_frame(buffer, out, chroma, info);
        if (ioctl_retrying(device_, fd_, VIDIOC_QBUF, &buffer) == -1) return lose(call_failed("VIDIOC_QBUF"));
        if (delivered) return CaptureResult::Frame;
    }
}

// Converts a dequeued buffer; false (and counted) when it holds no usable frame.
bool V4l2Camera::take_frame(const v4l2_buffer& buffer, GreyImage& out, Chroma& chroma, FrameInfo& info) {
    count_sequence(buffer.sequence);
    const char* failure = nullptr;
    if (buffer.index >= static_cast<std::uint32_t>(buffers_.count())) failure = "buffer index out of range";
    else if ((buffer.flags & V4L2_BUF_FLAG_ERROR) != 0) failure = "the driver flagged the buffer as damaged";
    else if (!converter_.convert(buffers_.data(buffer.index),
                                 std::min<std::size_t>(buffer.bytesused, buffers_.length(buffer.index)), out, chroma))
        failure = converter_.failure();
    if (failure != nullptr) {
        std::snprintf(last_corrupt_, sizeof last_corrupt_, "%s", failure);
        ++corrupt_;
        ++corrupt_since_frame_;
        return false;
    }
    if ((buffer.flags & V4L2_BUF_FLAG_TIMESTAMP_MASK) == V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC) {
        info.timestamp = kernel_time(buffer.timestamp);
        info.timestamp_source = (buffer.flags & V4L2_BUF_FLAG_TSTAMP_SRC_MASK) == V4L2_BUF_FLAG_TSTAMP_SRC_SOE
                                    ? TimestampSource::StartOfExposure
                                    : TimestampSource::EndOfFrame;
    } else {
        info.timestamp = clock_.now();
        info.timestamp_source = TimestampSource::Dequeue;
    }
    last_timestamp_source_ = info.timestamp_source;
    info.sequence = buffer.sequence;
    info.dropped = dropped_since_frame_;
    info.corrupt = corrupt_since_frame_;
    info.first_of_stream = first_of_stream_;
    dropped_since_frame_ = 0;
    corrupt_since_frame_ = 0;
    first_of_stream_ = false;
    ++frames_;
    return true;
}

// A gap in the driver's sequence numbers is frames it dropped. A step back (a driver that restarted
// its count) is not read as four billion drops.
void V4l2Camera::count_sequence(std::uint32_t sequence) {
    if (have_sequence_) {
        const std::uint32_t gap = sequence - last_sequence_ - 1u;
        if (gap < 0x80000000u) {
            dropped_since_frame_ += gap;
            drops_ += gap;
        }
    }
    have_sequence_ = true;
    last_sequence_ = sequence;
}

std::string V4l2Camera::status() const {
    char text[160];
    switch (state_) {
        case State::Closed: return "closed";
        case State::Failed: return "error: " + error_;
        case State::Lost: {
            const double wait = std::chrono::duration<double>(std::max(retry_at_ - clock_.now(), MonoClock::duration{})).count();
            std::snprintf(text, sizeof text, ", retry in %.1f s", wait);
            return "disconnected: " + error_ + text;
        }
        case State::Streaming: break;
    }
    std::string line = "streaming " + std::to_string(width()) + "x" + std::to_string(height()) + " " +
                       format_name(pixel_format());
    if (pixel_format() == PixelFormat::Mjpeg) line += " (scale 1/" + std::to_string(jpeg_scale_denom()) + ")";
    if (fps() > 0.0) {
        std::snprintf(text, sizeof text, " %.4g fps", fps());
        line += text;
    }
    if (frames_ > 0 && last_timestamp_source_ == TimestampSource::Dequeue) line += ", timestamps at dequeue";
    if (drops_ > 0) line += ", " + std::to_string(drops_) + " dropped";
    if (corrupt_ > 0) line += ", " + std::to_string(corrupt_) + " corrupt";
    return line;
}

}  // namespace rays::capture
