// SPDX-License-Identifier: Apache-2.0
// An in-memory CAN bus for tests and the bench: endpoints are CanTransports; a frame one endpoint
// sends is delivered to every other endpoint (as on a real bus, not back to its sender) and recorded
// with its time and sender. Faults on demand: ENOBUFS on an endpoint's sends, a muted endpoint (its
// frames are lost: a killed process or cut cable), bus-off (error frames to all, sends fail until
// cleared, then a restart error frame).
//
// Threads: each endpoint is used by one thread; wake(), the fault switches and records() from any.
// Queues and the record are allocated at construction; send and receive do not allocate.
#pragma once
#include <array>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "core/clock.hpp"
#include "drivers/can/can_transport.hpp"

namespace rays::can {

struct BusRecord {
    TimePoint time{};
    can_frame frame{};
    int sender = 0;  // endpoint number, in order of creation from 0
};

class LoopbackBus;

class LoopbackEndpoint final : public CanTransport {
public:
    static constexpr std::size_t kQueueCapacity = 4096;
    static constexpr int kSendRetries = 4;

    LoopbackEndpoint(LoopbackBus& bus, int number) : bus_(bus), number_(number) {}

    bool open(std::string& error) override;
    void close() override {}
    CanIo send(const can_frame& frame) override;
    CanIo receive(can_frame& frame, std::chrono::microseconds timeout) override;
    void wake() override;
    const char* last_error() const override { return "loopback: open refused"; }
    CanCounters counters() const override;

    int number() const { return number_; }
    // The next `attempts` send attempts find the queue full (ENOBUFS).
    void fail_sends_with_enobufs(int attempts) { enobufs_left_ = attempts; }
    void mute(bool muted) { muted_ = muted; }
    void refuse_open(bool refuse) { refuse_open_ = refuse; }

private:
    friend class LoopbackBus;
    void deliver(const can_frame& frame);  // from another endpoint's thread

    LoopbackBus& bus_;
    const int number_;
    std::mutex mutex_;
    std::condition_variable ready_;
    std::array<can_frame, kQueueCapacity> queue_{};
    std::size_t head_ = 0, count_ = 0;
    bool woken_ = false;
    std::atomic<int> enobufs_left_{0};
    std::atomic<bool> muted_{false}, refuse_open_{false};
    std::atomic<std::uint64_t> sent_{0}, received_{0}, retries_{0}, dropped_{0}, overflowed_{0};
};

class LoopbackBus {
public:
    explicit LoopbackBus(const Clock& clock, std::size_t record_capacity = 1 << 18);

    // Endpoints live as long as the bus.
    LoopbackEndpoint& add_endpoint();
    std::unique_ptr<CanTransport> transport_for(LoopbackEndpoint& endpoint);  // a non-owning handle

    // Called (under the bus lock, on the sender's thread) for every frame that goes onto the bus.
    void set_observer(std::function<void(const BusRecord&)> observer);
    void set_bus_off(bool off);
    std::vector<BusRecord> records() const;  // a copy, for tests
    const Clock& clock() const { return clock_; }

private:
    friend class LoopbackEndpoint;
    bool transmit(const LoopbackEndpoint& sender, const can_frame& frame);  // false while bus-off
    void broadcast_error(canid_t error_class);

    const Clock& clock_;
    mutable std::mutex mutex_;
    std::vector<std::unique_ptr<LoopbackEndpoint>> endpoints_;
    std::vector<BusRecord> records_;
    std::size_t record_capacity_;
    bool bus_off_ = false;
    std::function<void(const BusRecord&)> observer_;
};

}  // namespace rays::can
