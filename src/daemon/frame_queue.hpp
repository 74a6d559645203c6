// SPDX-License-Identifier: Apache-2.0
// Frames from the capture thread to the frame loop: a fixed ring of 128×128 frames with their
// source index and capture time, allocated once. A recorded source waits for room (no frame lost);
// a live camera overwrites the oldest unread frame and counts it as dropped. The frame loop copies
// a frame out and never holds the lock while tracking.
#pragma once
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <vector>

#include "core/clock.hpp"
#include "core/image.hpp"

namespace rays::daemon {

struct CapturedFrame {
    GreyImage image;
    Chroma chroma;         // present where the source has colour
    long index = -1;       // the source's own frame number
    TimePoint stamp{};     // capture time on the monotonic clock
    TimePoint arrived{};   // when it reached raysd; the tracking budget counts from here (stamp when unset)
};

class FrameQueue {
public:
    explicit FrameQueue(int capacity);

    enum class Push { Queued, Replaced, TimedOut, Closed };
    // Capture side. `wait_for_room`: block up to `timeout` while full; otherwise replace the oldest.
    Push push(const CapturedFrame& frame, bool wait_for_room, std::chrono::milliseconds timeout);

    // Frame loop: the oldest frame into `out`; false after `timeout` without one or when closed and empty.
    bool pop(CapturedFrame& out, std::chrono::nanoseconds timeout);

    // Wakes a waiting pop() without a frame (the capture side has news, or shutdown).
    void wake();
    void close();

    long dropped() const;
    int size() const;

private:
    mutable std::mutex mutex_;
    std::condition_variable frame_ready_;
    std::condition_variable room_ready_;
    std::vector<CapturedFrame> slots_;
    int head_ = 0;  // oldest
    int count_ = 0;
    long dropped_ = 0;
    bool closed_ = false;
    bool woken_ = false;
};

}  // namespace rays::daemon
