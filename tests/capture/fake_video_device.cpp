// SPDX-License-Identifier: Apache-2.0
#include "fake_video_device.hpp"

#include <poll.h>
#include <sys/mman.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace rays::test {
namespace {

constexpr std::uint32_t kOffsetStep = 1u << 16;  // QUERYBUF's mmap cookie: (index + 1) · step

bool is_raw(std::uint32_t fourcc) { return fourcc == V4L2_PIX_FMT_GREY || fourcc == V4L2_PIX_FMT_YUYV; }

timeval to_timeval(TimePoint t) {
    const auto us = std::chrono::duration_cast<std::chrono::microseconds>(t.time_since_epoch()).count();
    return timeval{static_cast<time_t>(us / 1000000), static_cast<suseconds_t>(us % 1000000)};
}

}  // namespace

FakeVideoDevice::FakeVideoDevice(FakeClock& clock, FakeDriverConfig config) : clock_(clock), config_(std::move(config)) {}

void FakeVideoDevice::push(FakeFrame frame) {
    if (!frame.sequence) frame.sequence = next_sequence_;
    next_sequence_ = *frame.sequence + 1;
    if (!frame.timestamp) frame.timestamp = to_timeval(clock_.now());
    pending_.push_back(std::move(frame));
}

void FakeVideoDevice::unplug() {
    present_ = false;
    if (session_) session_->dead = true;
    pending_.clear();
}

void FakeVideoDevice::replug(FakeDriverConfig config) {
    config_ = std::move(config);
    present_ = true;
    next_sequence_ = 0;
}

int FakeVideoDevice::held_by_camera() const {
    if (!session_) return 0;
    return static_cast<int>(std::count_if(session_->buffers.begin(), session_->buffers.end(),
                                          [](const auto& b) { return !b->queued; }));
}

std::vector<int> FakeVideoDevice::dequeues_per_buffer() const {
    std::vector<int> counts;
    if (session_)
        for (const auto& b : session_->buffers) counts.push_back(b->dequeues);
    return counts;
}

int FakeVideoDevice::fail(int error) {
    errno = error;
    return -1;
}

int FakeVideoDevice::open(const char* path, int flags) {
    open_attempts_.push_back(clock_.now());
    last_open_flags_ = flags;
    if (std::strcmp(path, "/dev/video0") != 0 || !present_) return fail(ENOENT);
    if (session_) violation("open while fd " + std::to_string(session_->fd) + " is still open");
    session_ = std::make_shared<Session>();
    session_->fd = next_fd_++;
    return session_->fd;
}

int FakeVideoDevice::close(int fd) {
    if (!session_ || fd != session_->fd) {
        violation("close of fd " + std::to_string(fd) + ", which is not open");
        return fail(EBADF);
    }
    session_.reset();  // mappings keep their buffers alive, as the kernel does
    return 0;
}

int FakeVideoDevice::ioctl(int fd, unsigned long request, void* arg) {
    if (!session_ || fd != session_->fd) {
        violation("ioctl on fd " + std::to_string(fd) + ", which is not open");
        return fail(EBADF);
    }
    if (session_->dead) return fail(ENODEV);
    if (auto it = injected_.find(request); it != injected_.end()) {
        const int error = it->second;
        injected_.erase(it);
        return fail(error);
    }
    return dispatch(*session_, request, arg);
}

int FakeVideoDevice::dispatch(Session& s, unsigned long request, void* arg) {
    switch (request) {
        case VIDIOC_QUERYCAP: {
            auto& cap = *static_cast<v4l2_capability*>(arg);
            cap = v4l2_capability{};
            std::strcpy(reinterpret_cast<char*>(cap.driver), "fake");
            std::strcpy(reinterpret_cast<char*>(cap.card), "Fake Camera");
            cap.device_caps = config_.device_caps;
            cap.capabilities = config_.device_caps | V4L2_CAP_DEVICE_CAPS;
            return 0;
        }
        case VIDIOC_ENUM_FMT: {
            auto& desc = *static_cast<v4l2_fmtdesc*>(arg);
            if (desc.type != V4L2_BUF_TYPE_VIDEO_CAPTURE || desc.index >= config_.formats.size()) return fail(EINVAL);
            desc.pixelformat = config_.formats[desc.index];
            return 0;
        }
        case VIDIOC_S_FMT: return set_format(s, *static_cast<v4l2_format*>(arg));
        case VIDIOC_G_PARM: return parm(s, *static_cast<v4l2_streamparm*>(arg), false);
        case VIDIOC_S_PARM: return parm(s, *static_cast<v4l2_streamparm*>(arg), true);
        case VIDIOC_REQBUFS: return request_buffers(s, *static_cast<v4l2_requestbuffers*>(arg));
        case VIDIOC_QUERYBUF: return query_buffer(s, *static_cast<v4l2_buffer*>(arg));
        case VIDIOC_QBUF: return queue_buffer(s, *static_cast<v4l2_buffer*>(arg));
        case VIDIOC_DQBUF: return dequeue_buffer(s, *static_cast<v4l2_buffer*>(arg));
        case VIDIOC_STREAMON:
            if (s.buffers.empty()) return fail(EINVAL);
            s.streaming = true;
            return 0;
        case VIDIOC_STREAMOFF:  // as vb2: every buffer comes back to the application
            s.streaming = false;
            s.queue.clear();
            for (auto& b : s.buffers) b->queued = false;
            return 0;
        default: return fail(ENOTTY);
    }
}

// Like a real driver, S_FMT never refuses a format: it falls back to its first one.
int FakeVideoDevice::set_format(Session& s, v4l2_format& format) {
    if (format.type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
    if (!s.buffers.empty()) {
        violation("S_FMT with buffers allocated");
        return fail(EBUSY);
    }
    v4l2_pix_format& pix = format.fmt.pix;
    const auto& offered = config_.formats;
    if (std::find(offered.begin(), offered.end(), pix.pixelformat) == offered.end()) pix.pixelformat = offered.front();
    if (config_.granted_width > 0) {
        pix.width = static_cast<std::uint32_t>(config_.granted_width);
        pix.height = static_cast<std::uint32_t>(config_.granted_height);
    }
    const std::uint32_t bpp = pix.pixelformat == V4L2_PIX_FMT_YUYV ? 2 : 1;
    pix.field = V4L2_FIELD_NONE;
    pix.bytesperline = is_raw(pix.pixelformat) ? pix.width * bpp + static_cast<std::uint32_t>(config_.line_padding) : 0;
    pix.sizeimage = is_raw(pix.pixelformat) ? pix.bytesperline * pix.height : pix.width * pix.height * 2;
    s.fourcc = pix.pixelformat;
    s.width = static_cast<int>(pix.width);
    s.height = static_cast<int>(pix.height);
    s.bytes_per_line = pix.bytesperline;
    s.size_image = pix.sizeimage;
    return 0;
}

int FakeVideoDevice::parm(Session& s, v4l2_streamparm& parm, bool set) {
    if (!config_.frame_intervals) return fail(ENOTTY);
    if (parm.type != V4L2_BUF_TYPE_VIDEO_CAPTURE) return fail(EINVAL);
    if (set) {
        const v4l2_fract asked = parm.parm.capture.timeperframe;
        if (asked.numerator > 0 && asked.denominator > 0)
            s.fps = std::clamp(static_cast<int>(asked.denominator / asked.numerator), 1, config_.max_fps);
    }
    parm.parm.capture = v4l2_captureparm{};
    parm.parm.capture.capability = V4L2_CAP_TIMEPERFRAME;
    parm.parm.capture.timeperframe = v4l2_fract{1, static_cast<std::uint32_t>(s.fps)};
    return 0;
}

int FakeVideoDevice::request_buffers(Session& s, v4l2_requestbuffers& request) {
    if (request.type != V4L2_BUF_TYPE_VIDEO_CAPTURE || request.memory != V4L2_MEMORY_MMAP) return fail(EINVAL);
    if (s.streaming || std::any_of(s.buffers.begin(), s.buffers.end(), [](const auto& b) { return b->mapped; })) {
        violation("REQBUFS while streaming or mapped");
        return fail(EBUSY);
    }
    s.buffers.clear();
    s.queue.clear();
    request.count = std::min(request.count, static_cast<std::uint32_t>(config_.max_buffers));
    for (std::uint32_t i = 0; i < request.count; ++i) {
        s.buffers.push_back(std::make_unique<Buffer>());
        s.buffers.back()->memory.assign(s.size_image, 0);
    }
    return 0;
}

int FakeVideoDevice::query_buffer(Session& s, v4l2_buffer& buffer) {
    if (buffer.type != V4L2_BUF_TYPE_VIDEO_CAPTURE || buffer.index >= s.buffers.size()) return fail(EINVAL);
    buffer.memory = V4L2_MEMORY_MMAP;
    buffer.length = s.size_image;
    buffer.m.offset = (buffer.index + 1) * kOffsetStep;
    return 0;
}

int FakeVideoDevice::queue_buffer(Session& s, v4l2_buffer& buffer) {
    if (buffer.type != V4L2_BUF_TYPE_VIDEO_CAPTURE || buffer.memory != V4L2_MEMORY_MMAP ||
        buffer.index >= s.buffers.size()) {
        violation("QBUF of an invalid buffer " + std::to_string(buffer.index));
        return fail(EINVAL);
    }
    Buffer& b = *s.buffers[buffer.index];
    if (b.queued) {
        violation("QBUF of buffer " + std::to_string(buffer.index) + ", which the driver holds already");
        return fail(EINVAL);
    }
    if (!b.mapped) violation("QBUF of buffer " + std::to_string(buffer.index) + " before it is mapped");
    b.queued = true;
    s.queue.push_back(buffer.index);
    return 0;
}

int FakeVideoDevice::dequeue_buffer(Session& s, v4l2_buffer& buffer) {
    if (buffer.type != V4L2_BUF_TYPE_VIDEO_CAPTURE || buffer.memory != V4L2_MEMORY_MMAP || !s.streaming)
        return fail(EINVAL);
    if (s.queue.empty() || pending_.empty()) return fail(EAGAIN);
    const std::uint32_t index = s.queue.front();
    s.queue.pop_front();
    Buffer& b = *s.buffers[index];
    const FakeFrame& frame = pending_.front();
    const std::size_t bytes = std::min(frame.data.size(), b.memory.size());
    std::copy_n(frame.data.begin(), bytes, b.memory.begin());
    buffer.index = index;
    buffer.bytesused = static_cast<std::uint32_t>(bytes);
    buffer.length = static_cast<std::uint32_t>(b.memory.size());
    buffer.sequence = *frame.sequence;
    buffer.timestamp = *frame.timestamp;
    buffer.flags = config_.timestamp_flags | frame.extra_flags | V4L2_BUF_FLAG_MAPPED;
    buffer.field = V4L2_FIELD_NONE;
    pending_.pop_front();
    b.queued = false;
    ++b.dequeues;
    return 0;
}

void* FakeVideoDevice::mmap(std::size_t length, int prot, int flags, int fd, off_t offset) {
    if (!session_ || fd != session_->fd || session_->dead) {
        errno = ENODEV;
        return MAP_FAILED;
    }
    const auto index = static_cast<std::uint32_t>(offset / kOffsetStep) - 1u;
    if (offset % kOffsetStep != 0 || index >= session_->buffers.size() || (prot & PROT_READ) == 0 ||
        (flags & MAP_SHARED) == 0) {
        violation("mmap with a bad offset, protection or flags");
        errno = EINVAL;
        return MAP_FAILED;
    }
    Buffer& b = *session_->buffers[index];
    if (length != b.memory.size() || b.mapped) {
        violation("mmap of buffer " + std::to_string(index) + " with a wrong length or twice");
        errno = EINVAL;
        return MAP_FAILED;
    }
    b.mapped = true;
    mappings_[b.memory.data()] = Mapping{session_, index, length};
    return b.memory.data();
}

int FakeVideoDevice::munmap(void* address, std::size_t length) {
    const auto it = mappings_.find(address);
    if (it == mappings_.end() || it->second.length != length) {
        violation("munmap of memory that is not a mapped buffer");
        return fail(EINVAL);
    }
    it->second.session->buffers[it->second.index]->mapped = false;
    mappings_.erase(it);
    return 0;
}

// As vb2: an error while not streaming or with nothing queued; readable when a frame is waiting.
// Waiting moves the fake clock by the whole timeout.
int FakeVideoDevice::poll(int fd, int timeout_ms) {
    if (poll_error_ != 0) {
        const int error = poll_error_;
        poll_error_ = 0;
        return fail(error);
    }
    if (fd >= 0) {
        if (!session_ || fd != session_->fd) {
            violation("poll on fd " + std::to_string(fd) + ", which is not open");
            return POLLNVAL;
        }
        if (session_->dead) return POLLERR | POLLHUP;
        if (!session_->streaming || session_->queue.empty()) return POLLERR;
        if (!pending_.empty()) return POLLIN | POLLRDNORM;
    }
    clock_.advance(std::chrono::milliseconds{timeout_ms});
    return 0;
}

}  // namespace rays::test
