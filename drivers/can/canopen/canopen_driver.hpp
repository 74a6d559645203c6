// SPDX-License-Identifier: Apache-2.0
// PtuDriver for two CiA 402 drives over CANopen (SocketCAN). The I/O thread (CanIoDriver) runs
// both CanopenAxis state machines and produces raysd's own heartbeat (0x700 + master_id, state
// Operational, every master_heartbeat_ms: CiA 301 §7.2.8.3.2.2), which each drive consumes
// (0x1016) so that it stops by itself (0x6007) when raysd dies, even by SIGKILL.
// On a fault on one axis the other is stopped too; commands move the axes again once every fault
// has cleared and a fresh command arrives.
#pragma once
#include <array>
#include <memory>
#include <string>

#include "drivers/can/can_io_driver.hpp"
#include "drivers/can/canopen/canopen_axis.hpp"
#include "drivers/can/canopen/canopen_settings.hpp"

namespace rays::canopen {

class CanopenDriver final : public can::CanIoDriver, private can::FrameSink {
public:
    CanopenDriver(const CanopenSettings& settings, std::unique_ptr<can::CanTransport> transport, const Clock& clock);
    ~CanopenDriver() override;

    const char* name() const override { return "canopen"; }
    double command_latency_s() const override;
    ptu::DriverStatus home(TimePoint now) override;

private:
    void io_start(TimePoint now) override;
    void io_frame(const can_frame& frame, TimePoint now) override;
    void io_bus_event(can::CanBusEvent event, TimePoint now) override;
    void io_cycle(const ptu::PtuCommand& command, bool fresh, TimePoint now) override;
    void io_stop(TimePoint now) override;
    can::IoReport io_report(TimePoint now) override;
    bool send_frame(const can_frame& frame) override { return send(frame); }

    const CanopenSettings settings_;
    std::array<CanopenAxis, ptu::kAxes> axes_;
    TimePoint next_heartbeat_{};
    bool bus_off_ = false;
};

// Null with `error` for an invalid combination (equal node ids, ...). The real SocketCAN transport.
std::unique_ptr<ptu::PtuDriver> make_canopen_driver(const CanopenSettings& settings, const Clock& clock,
                                                    std::string& error);
// The same on a given transport (tests, bench: a LoopbackBus endpoint).
std::unique_ptr<ptu::PtuDriver> make_canopen_driver(const CanopenSettings& settings,
                                                    std::unique_ptr<can::CanTransport> transport, const Clock& clock,
                                                    std::string& error);

}  // namespace rays::canopen
