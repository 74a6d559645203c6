// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/sim/sim_bus_host.hpp"

namespace rays::can {

SimBusHost::SimBusHost(LoopbackBus& bus, std::vector<SimNode*> nodes)
    : endpoint_(bus.add_endpoint()), clock_(bus.clock()), nodes_(std::move(nodes)), thread_([this] { run(); }) {}

SimBusHost::~SimBusHost() {
    running_ = false;
    endpoint_.wake();
    thread_.join();
}

void SimBusHost::run() {
    TimePoint next_tick = clock_.now();
    while (running_) {
        can_frame frame{};
        const CanIo result = endpoint_.receive(frame, std::chrono::microseconds(500));
        const TimePoint now = clock_.now();
        if (result == CanIo::Ok && classify_error_frame(frame) == CanBusEvent::None)
            for (SimNode* node : nodes_) node->on_frame(frame, now, *this);
        if (now >= next_tick) {
            for (SimNode* node : nodes_) node->tick(now, *this);
            next_tick = now + std::chrono::milliseconds(1);
        }
    }
}

}  // namespace rays::can
