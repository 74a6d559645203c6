// SPDX-License-Identifier: Apache-2.0
// The capture side: a thread that takes frames from the FrameSource and queues them for the frame
// loop, tells the loop when the camera goes away or comes back, and keeps a status line.
#pragma once
#include <atomic>
#include <mutex>
#include <string>
#include <thread>

#include "daemon/frame_source.hpp"
#include "daemon/loop_channels.hpp"

namespace rays::daemon {

class CaptureThread {
public:
    CaptureThread(FrameSource& source, LoopChannels& channels, const Clock& clock);
    ~CaptureThread();

    void start();
    // Stops and joins; a source stuck in a blocking read (a silent FIFO) is left behind after `grace`.
    void stop(std::chrono::milliseconds grace);

    std::string status() const;
    long delivered() const { return delivered_.load(std::memory_order_relaxed); }

private:
    void run();
    void set_status(std::string text);
    bool queue(const CapturedFrame& frame);

    FrameSource& source_;
    LoopChannels& channels_;
    const Clock& clock_;
    std::thread thread_;
    std::atomic<bool> stop_{false};
    std::atomic<bool> finished_{false};
    std::atomic<long> delivered_{0};
    mutable std::mutex status_mutex_;
    std::string status_;
};

}  // namespace rays::daemon
