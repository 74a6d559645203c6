// SPDX-License-Identifier: Apache-2.0
// CanTransport on a Linux SocketCAN interface ("can0"): a PF_CAN raw socket bound to it,
// non-blocking, with error frames enabled for bus-off and controller problems (reported by
// receive() as frames with CAN_ERR_FLAG, see classify_error_frame), and an eventfd for wake().
// A send that finds the controller's queue full (ENOBUFS) is retried a few times with a short
// doubling pause (at most ~1 ms in all, on the I/O thread) and then dropped; both are counted.
#pragma once
#include <atomic>
#include <string>

#include "drivers/can/can_transport.hpp"

namespace rays::can {

class SocketCanTransport final : public CanTransport {
public:
    static constexpr int kSendRetries = 4;  // pauses of 100, 200, 400 and 800 µs

    explicit SocketCanTransport(std::string interface_name);
    ~SocketCanTransport() override;
    SocketCanTransport(const SocketCanTransport&) = delete;
    SocketCanTransport& operator=(const SocketCanTransport&) = delete;

    bool open(std::string& error) override;
    void close() override;
    CanIo send(const can_frame& frame) override;
    CanIo receive(can_frame& frame, std::chrono::microseconds timeout) override;
    void wake() override;
    const char* last_error() const override { return error_; }
    CanCounters counters() const override;

private:
    void note_error(const char* what, int error_number);

    std::string interface_;
    int socket_ = -1;
    int wake_fd_ = -1;
    char error_[160] = {};
    std::atomic<std::uint64_t> sent_{0}, received_{0}, retries_{0}, dropped_{0};
};

}  // namespace rays::can
