// SPDX-License-Identifier: Apache-2.0
// Runs simulated CAN nodes (drives) on their own thread, on one endpoint of a LoopbackBus: each
// received frame goes to every node, and every node ticks each millisecond.
#pragma once
#include <atomic>
#include <thread>
#include <vector>

#include "core/clock.hpp"
#include "drivers/can/sim/loopback_bus.hpp"

namespace rays::can {

class SimNode {
public:
    virtual ~SimNode() = default;
    virtual void on_frame(const can_frame& frame, TimePoint now, FrameSink& bus) = 0;
    virtual void tick(TimePoint now, FrameSink& bus) = 0;
};

class SimBusHost final : private FrameSink {
public:
    SimBusHost(LoopbackBus& bus, std::vector<SimNode*> nodes);
    ~SimBusHost() override;
    SimBusHost(const SimBusHost&) = delete;
    SimBusHost& operator=(const SimBusHost&) = delete;

    LoopbackEndpoint& endpoint() { return endpoint_; }

private:
    bool send_frame(const can_frame& frame) override { return endpoint_.send(frame) == CanIo::Ok; }
    void run();

    LoopbackEndpoint& endpoint_;
    const Clock& clock_;
    std::vector<SimNode*> nodes_;
    std::atomic<bool> running_{true};
    std::thread thread_;
};

}  // namespace rays::can
