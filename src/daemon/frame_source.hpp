// SPDX-License-Identifier: Apache-2.0
// Where frames come from (V4L2 camera, file replay, later the simulated camera), seen from the
// capture thread: each call delivers one 128×128 frame with the source's own index and its capture
// time. Sources may block, allocate and decode; the frame loop never calls them.
#pragma once
#include <chrono>
#include <string>

#include "daemon/frame_queue.hpp"

namespace rays::daemon {

class FrameSource {
public:
    virtual ~FrameSource() = default;

    enum class Result {
        Frame,         // `out` holds a new frame
        Timeout,       // nothing within the timeout; call again
        End,           // a recorded sequence ended (and does not loop)
        Disconnected,  // the device went away; the source retries by itself on later calls
        Error,         // unrecoverable; describe() says why
    };

    virtual Result next(CapturedFrame& out, std::chrono::milliseconds timeout) = 0;

    // A live source drops the oldest queued frame when the loop falls behind; a recorded one waits.
    virtual bool live() const = 0;

    // One line for status and logs: "replay demo.y4m 128x128 at 25 fps, frame 120".
    virtual std::string describe() const = 0;
};

}  // namespace rays::daemon
