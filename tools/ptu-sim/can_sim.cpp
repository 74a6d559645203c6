// SPDX-License-Identifier: Apache-2.0
#include "can_sim.hpp"

#include <cstdio>

#include "drivers/can/sim/cia402_sim_drive.hpp"
#include "drivers/can/socket_can_transport.hpp"

namespace rays::ptusim {
namespace {

// The drives' frames go out on the interface.
class TransportSink final : public can::FrameSink {
public:
    explicit TransportSink(can::CanTransport& transport) : transport_(transport) {}
    bool send_frame(const can_frame& frame) override { return transport_.send(frame) == can::CanIo::Ok; }

private:
    can::CanTransport& transport_;
};

}  // namespace

int run_can_sim(const std::string& interface, int pan_node, int tilt_node, const std::atomic<bool>& stop) {
    can::SocketCanTransport transport(interface);
    std::string error;
    if (!transport.open(error)) {
        std::fprintf(stderr, "ptu-sim: %s\n", error.c_str());
        return 1;
    }
    canopen::Cia402SimConfig pan_config, tilt_config;
    pan_config.node = pan_node;
    tilt_config.node = tilt_node;
    canopen::Cia402SimDrive pan(pan_config), tilt(tilt_config);
    TransportSink sink(transport);
    std::printf("ready\n");
    std::fflush(stdout);
    TimePoint next_tick = MonoClock::now();
    while (!stop) {
        can_frame frame{};
        can::CanIo got = transport.receive(frame, std::chrono::milliseconds(1));
        TimePoint now = MonoClock::now();
        if (got == can::CanIo::Ok) {
            pan.on_frame(frame, now, sink);
            tilt.on_frame(frame, now, sink);
        } else if (got == can::CanIo::Down) {
            std::fprintf(stderr, "ptu-sim: %s: %s\n", interface.c_str(), transport.last_error());
            return 1;
        }
        if (now >= next_tick) {  // each drive's 1 ms cycle: heartbeats, TPDOs, motion, watchdog
            pan.tick(now, sink);
            tilt.tick(now, sink);
            next_tick = now + std::chrono::milliseconds(1);
        }
    }
    return 0;
}

}  // namespace rays::ptusim
