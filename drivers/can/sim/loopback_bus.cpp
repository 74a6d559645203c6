// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/sim/loopback_bus.hpp"

#include <linux/can/error.h>

namespace rays::can {
namespace {

// Lets a driver own "its" transport while the bus keeps the endpoint.
class EndpointHandle final : public CanTransport {
public:
    explicit EndpointHandle(LoopbackEndpoint& endpoint) : endpoint_(endpoint) {}
    bool open(std::string& error) override { return endpoint_.open(error); }
    void close() override { endpoint_.close(); }
    CanIo send(const can_frame& frame) override { return endpoint_.send(frame); }
    CanIo receive(can_frame& frame, std::chrono::microseconds timeout) override {
        return endpoint_.receive(frame, timeout);
    }
    void wake() override { endpoint_.wake(); }
    const char* last_error() const override { return endpoint_.last_error(); }
    CanCounters counters() const override { return endpoint_.counters(); }

private:
    LoopbackEndpoint& endpoint_;
};

}  // namespace

bool LoopbackEndpoint::open(std::string& error) {
    if (!refuse_open_) return true;
    error = last_error();
    return false;
}

CanIo LoopbackEndpoint::send(const can_frame& frame) {
    for (int attempt = 0;; ++attempt) {
        if (enobufs_left_.load() <= 0) break;
        --enobufs_left_;
        if (attempt == kSendRetries) {
            ++dropped_;
            return CanIo::Busy;
        }
        ++retries_;
    }
    if (muted_) return CanIo::Ok;  // gone on the wire: nobody receives it
    if (!bus_.transmit(*this, frame)) {
        ++dropped_;
        return CanIo::Busy;
    }
    ++sent_;
    return CanIo::Ok;
}

CanIo LoopbackEndpoint::receive(can_frame& frame, std::chrono::microseconds timeout) {
    std::unique_lock lock(mutex_);
    if (!ready_.wait_for(lock, timeout, [&] { return count_ > 0 || woken_; })) return CanIo::Timeout;
    if (count_ == 0) {
        woken_ = false;
        return CanIo::Woken;
    }
    frame = queue_[head_];
    head_ = (head_ + 1) % kQueueCapacity;
    --count_;
    ++received_;
    return CanIo::Ok;
}

void LoopbackEndpoint::wake() {
    // try_lock: the frame loop never waits; if the lock is busy its holder is about to look anyway,
    // and the next receive timeout bounds the delay.
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (lock.owns_lock()) {
        woken_ = true;
        lock.unlock();
    }
    ready_.notify_one();
}

void LoopbackEndpoint::deliver(const can_frame& frame) {
    {
        std::lock_guard lock(mutex_);
        if (count_ == kQueueCapacity) {
            ++overflowed_;
            return;
        }
        queue_[(head_ + count_) % kQueueCapacity] = frame;
        ++count_;
    }
    ready_.notify_one();
}

CanCounters LoopbackEndpoint::counters() const { return {sent_, received_, retries_, dropped_}; }

LoopbackBus::LoopbackBus(const Clock& clock, std::size_t record_capacity)
    : clock_(clock), record_capacity_(record_capacity) {
    records_.reserve(record_capacity);
}

LoopbackEndpoint& LoopbackBus::add_endpoint() {
    std::lock_guard lock(mutex_);
    endpoints_.push_back(std::make_unique<LoopbackEndpoint>(*this, static_cast<int>(endpoints_.size())));
    return *endpoints_.back();
}

std::unique_ptr<CanTransport> LoopbackBus::transport_for(LoopbackEndpoint& endpoint) {
    return std::make_unique<EndpointHandle>(endpoint);
}

bool LoopbackBus::transmit(const LoopbackEndpoint& sender, const can_frame& frame) {
    std::lock_guard lock(mutex_);
    if (bus_off_) return false;
    const BusRecord record{clock_.now(), frame, sender.number()};
    if (records_.size() < record_capacity_) records_.push_back(record);
    if (observer_) observer_(record);
    for (const auto& endpoint : endpoints_)
        if (endpoint.get() != &sender) endpoint->deliver(frame);
    return true;
}

void LoopbackBus::broadcast_error(canid_t error_class) {
    can_frame frame{};
    frame.can_id = CAN_ERR_FLAG | error_class;
    frame.len = CAN_ERR_DLC;
    for (const auto& endpoint : endpoints_) endpoint->deliver(frame);
}

void LoopbackBus::set_observer(std::function<void(const BusRecord&)> observer) {
    std::lock_guard lock(mutex_);
    observer_ = std::move(observer);
}

void LoopbackBus::set_bus_off(bool off) {
    std::lock_guard lock(mutex_);
    if (off == bus_off_) return;
    bus_off_ = off;
    broadcast_error(off ? CAN_ERR_BUSOFF : CAN_ERR_RESTARTED);
}

std::vector<BusRecord> LoopbackBus::records() const {
    std::lock_guard lock(mutex_);
    return records_;
}

}  // namespace rays::can
