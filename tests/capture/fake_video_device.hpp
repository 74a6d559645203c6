// SPDX-License-Identifier: Apache-2.0
// An in-memory V4L2 capture driver behind the VideoDevice seam. It answers the ioctls the camera uses
// as a vb2 driver would, holds real buffer memory for mmap, delivers frames the test pushes, and can
// be unplugged and plugged back with other formats. Misuse a real driver would tolerate or refuse
// quietly (requeueing a queued buffer, unmapping what is not mapped, a second open) is recorded in
// violations() so tests fail loudly.
#pragma once
#include <linux/videodev2.h>

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "capture/video_device.hpp"
#include "fake_clock.hpp"

namespace rays::test {

struct FakeDriverConfig {
    std::vector<std::uint32_t> formats{V4L2_PIX_FMT_GREY};  // in ENUM_FMT order
    int granted_width = 0;   // S_FMT grants this size; 0: what was asked
    int granted_height = 0;
    int line_padding = 0;    // extra bytes at the end of each row of a raw format
    int max_buffers = 8;
    int max_fps = 30;        // S_PARM grants at most this
    bool frame_intervals = true;  // G_PARM/S_PARM supported
    std::uint32_t device_caps = V4L2_CAP_VIDEO_CAPTURE | V4L2_CAP_STREAMING;
    std::uint32_t timestamp_flags = V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC | V4L2_BUF_FLAG_TSTAMP_SRC_EOF;
};

struct FakeFrame {
    std::vector<std::uint8_t> data;
    std::optional<std::uint32_t> sequence;  // empty: one more than the previous frame's
    std::optional<timeval> timestamp;       // empty: the clock's time when pushed
    std::uint32_t extra_flags = 0;          // e.g. V4L2_BUF_FLAG_ERROR
};

class FakeVideoDevice final : public capture::VideoDevice {
public:
    explicit FakeVideoDevice(FakeClock& clock, FakeDriverConfig config = {});

    // The test's side.
    void push(FakeFrame frame);
    void push(std::vector<std::uint8_t> data) { push(FakeFrame{std::move(data), {}, {}, 0}); }
    void unplug();                          // the open fd dies; open() fails with ENOENT
    void replug(FakeDriverConfig config);   // present again, perhaps with other formats
    void fail_next(unsigned long request, int error) { injected_[request] = error; }
    void fail_next_poll(int error) { poll_error_ = error; }  // e.g. EINTR for a signal

    const std::vector<std::string>& violations() const { return violations_; }
    const std::vector<TimePoint>& open_attempts() const { return open_attempts_; }
    int last_open_flags() const { return last_open_flags_; }
    bool is_open() const { return session_ != nullptr; }
    bool streaming() const { return session_ != nullptr && session_->streaming; }
    std::size_t mapped() const { return mappings_.size(); }
    std::size_t pending() const { return pending_.size(); }
    int buffer_count() const { return session_ ? static_cast<int>(session_->buffers.size()) : 0; }
    int held_by_camera() const;                 // buffers dequeued and not yet queued again
    std::vector<int> dequeues_per_buffer() const;
    std::uint32_t format_set() const { return session_ ? session_->fourcc : 0; }
    int fps_set() const { return session_ ? session_->fps : 0; }

    // VideoDevice
    int open(const char* path, int flags) override;
    int close(int fd) override;
    int ioctl(int fd, unsigned long request, void* arg) override;
    void* mmap(std::size_t length, int prot, int flags, int fd, off_t offset) override;
    int munmap(void* address, std::size_t length) override;
    int poll(int fd, int timeout_ms) override;

private:
    struct Buffer {
        std::vector<std::uint8_t> memory;
        bool queued = false;
        bool mapped = false;
        int dequeues = 0;
    };
    struct Session {
        int fd = -1;
        bool dead = false;
        bool streaming = false;
        std::uint32_t fourcc = 0;
        int width = 0;
        int height = 0;
        std::uint32_t bytes_per_line = 0;
        std::uint32_t size_image = 0;
        int fps = 30;
        std::vector<std::unique_ptr<Buffer>> buffers;  // stable addresses for mappings
        std::deque<std::uint32_t> queue;               // queued indices, oldest first
    };
    struct Mapping {
        std::shared_ptr<Session> session;  // keeps the memory of a closed or unplugged session
        std::uint32_t index = 0;
        std::size_t length = 0;
    };

    int fail(int error);
    int dispatch(Session& s, unsigned long request, void* arg);
    int set_format(Session& s, v4l2_format& format);
    int request_buffers(Session& s, v4l2_requestbuffers& request);
    int query_buffer(Session& s, v4l2_buffer& buffer);
    int queue_buffer(Session& s, v4l2_buffer& buffer);
    int dequeue_buffer(Session& s, v4l2_buffer& buffer);
    int parm(Session& s, v4l2_streamparm& parm, bool set);
    void violation(std::string what) { violations_.push_back(std::move(what)); }

    FakeClock& clock_;
    FakeDriverConfig config_;
    bool present_ = true;
    int next_fd_ = 100;
    std::shared_ptr<Session> session_;
    std::map<void*, Mapping> mappings_;
    std::deque<FakeFrame> pending_;
    std::uint32_t next_sequence_ = 0;
    std::map<unsigned long, int> injected_;
    int poll_error_ = 0;
    std::vector<std::string> violations_;
    std::vector<TimePoint> open_attempts_;
    int last_open_flags_ = 0;
};

}  // namespace rays::test
