// SPDX-License-Identifier: Apache-2.0
// The hand-overs around the frame loop, owned by the daemon and shared by its three threads:
// capture → frames → loop; socket thread → commands → loop; loop → telemetry, status, snapshot,
// log lines → socket thread (woken through an eventfd). All sized once at start.
#pragma once
#include <atomic>

#include "daemon/frame_queue.hpp"
#include "common/latest_value.hpp"
#include "daemon/loop_log.hpp"
#include "daemon/loop_messages.hpp"
#include "common/spsc_ring.hpp"

namespace rays::daemon {

struct LoopChannels {
    explicit LoopChannels(int queue_frames);
    ~LoopChannels();
    LoopChannels(const LoopChannels&) = delete;
    LoopChannels& operator=(const LoopChannels&) = delete;

    // Frame loop: tells the socket thread there is telemetry or a log line to take. Non-blocking.
    void wake_socket_thread();
    // Socket thread: clears the wake-up after poll() reported it.
    void clear_wake();

    FrameQueue frames;
    SpscRing<LoopCommand, 64> commands;
    SpscRing<FrameTelemetry, 1024> telemetry;
    LatestValue<LoopStatus> status;
    LatestValue<SnapshotFrame> snapshot;
    LoopLog log;
    std::atomic<bool> stop{false};
    std::atomic<bool> camera_connected{false};
    int wake_fd = -1;  // eventfd, readable when the frame loop has news
};

}  // namespace rays::daemon
