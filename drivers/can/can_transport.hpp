// SPDX-License-Identifier: Apache-2.0
// The seam between a CAN driver and the bus: plain Linux `struct can_frame`s (<linux/can.h>) sent
// and received one at a time. SocketCanTransport is the real bus; LoopbackBus (sim/) connects a
// driver to simulated drives in memory. A transport is used by one I/O thread; only wake() may be
// called from any other thread (the frame loop, after handing over a new command).
#pragma once
#include <linux/can.h>

#include <chrono>
#include <cstdint>
#include <string>

namespace rays::can {

enum class CanIo {
    Ok,       // a frame was sent / received (error frames too: CAN_ERR_FLAG in can_id)
    Timeout,  // receive: nothing arrived in time
    Woken,    // receive: wake() was called
    Busy,     // send: the controller's queue stayed full (ENOBUFS) through the retries; frame dropped
    Down,     // the interface failed (last_error() says why); reopen with backoff
};

struct CanCounters {
    std::uint64_t sent = 0;
    std::uint64_t received = 0;
    std::uint64_t enobufs_retries = 0;  // sends retried after ENOBUFS
    std::uint64_t dropped = 0;          // sends given up (Busy)
};

class CanTransport {
public:
    virtual ~CanTransport() = default;
    // Opens (or reopens) the interface. May block and allocate; false with `error` on failure.
    virtual bool open(std::string& error) = 0;
    virtual void close() = 0;
    // Never blocks for long: a full queue is retried with a short bounded backoff, then Busy.
    virtual CanIo send(const can_frame& frame) = 0;
    // Waits at most `timeout` for the next frame.
    virtual CanIo receive(can_frame& frame, std::chrono::microseconds timeout) = 0;
    // Any thread, non-blocking: the current (or next) receive returns Woken.
    virtual void wake() = 0;
    virtual const char* last_error() const = 0;
    virtual CanCounters counters() const = 0;
};

// Where a protocol's I/O-thread code sends its frames (the driver, which counts failures).
class FrameSink {
public:
    virtual ~FrameSink() = default;
    virtual bool send_frame(const can_frame& frame) = 0;
};

// What an error frame (CAN_ERR_FLAG, <linux/can/error.h>) reports.
enum class CanBusEvent { None, BusOff, ControllerProblem, Restarted, Other };
CanBusEvent classify_error_frame(const can_frame& frame);

}  // namespace rays::can
