// SPDX-License-Identifier: Apache-2.0
#include "daemon/frame_queue.hpp"

namespace rays::daemon {

FrameQueue::FrameQueue(int capacity) : slots_(static_cast<std::size_t>(capacity)) {}

FrameQueue::Push FrameQueue::push(const CapturedFrame& frame, bool wait_for_room, std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    const int capacity = static_cast<int>(slots_.size());
    Push result = Push::Queued;
    if (wait_for_room) {
        if (!room_ready_.wait_for(lock, timeout, [&] { return closed_ || count_ < capacity; }))
            return Push::TimedOut;
        if (closed_) return Push::Closed;
    } else if (closed_) {
        return Push::Closed;
    } else if (count_ == capacity) {
        head_ = (head_ + 1) % capacity;
        --count_;
        ++dropped_;
        result = Push::Replaced;
    }
    CapturedFrame& slot = slots_[static_cast<std::size_t>((head_ + count_) % capacity)];
    slot.image = frame.image;  // same fixed size: a copy, no allocation
    slot.chroma = frame.chroma;
    slot.index = frame.index;
    slot.stamp = frame.stamp;
    ++count_;
    lock.unlock();
    frame_ready_.notify_one();
    return result;
}

bool FrameQueue::pop(CapturedFrame& out, std::chrono::nanoseconds timeout) {
    std::unique_lock lock(mutex_);
    frame_ready_.wait_for(lock, timeout, [&] { return count_ > 0 || closed_ || woken_; });
    woken_ = false;
    if (count_ == 0) return false;
    const CapturedFrame& slot = slots_[static_cast<std::size_t>(head_)];
    out.image = slot.image;
    out.chroma = slot.chroma;
    out.index = slot.index;
    out.stamp = slot.stamp;
    head_ = (head_ + 1) % static_cast<int>(slots_.size());
    --count_;
    lock.unlock();
    room_ready_.notify_one();
    return true;
}

void FrameQueue::wake() {
    {
        std::lock_guard lock(mutex_);
        woken_ = true;
    }
    frame_ready_.notify_one();
}

void FrameQueue::close() {
    {
        std::lock_guard lock(mutex_);
        closed_ = true;
    }
    frame_ready_.notify_all();
    room_ready_.notify_all();
}

long FrameQueue::dropped() const {
    std::lock_guard lock(mutex_);
    return dropped_;
}

int FrameQueue::size() const {
    std::lock_guard lock(mutex_);
    return count_;
}

}  // namespace rays::daemon
