// SPDX-License-Identifier: Apache-2.0
// PtuDriver for two ODrive axes over the CAN simple protocol (SocketCAN). The I/O thread
// (CanIoDriver) runs both OdriveAxis state machines; on a fault on one axis the other is stopped
// too; commands move the axes again once every fault has cleared and a fresh command arrives.
// The drive-side watchdog must be enabled on the ODrive itself (see odrive_settings.hpp).
#pragma once
#include <array>
#include <memory>
#include <string>

#include "drivers/can/can_io_driver.hpp"
#include "drivers/can/odrive/odrive_axis.hpp"
#include "drivers/can/odrive/odrive_settings.hpp"

namespace rays::odrive {

class OdriveDriver final : public can::CanIoDriver, private can::FrameSink {
public:
    OdriveDriver(const OdriveSettings& settings, std::unique_ptr<can::CanTransport> transport, const Clock& clock);
    ~OdriveDriver() override;

    const char* name() const override { return "odrive"; }
    double command_latency_s() const override { return settings_.cycle_ms / 1000.0; }
    ptu::DriverStatus home(TimePoint now) override;

private:
    void io_start(TimePoint now) override;
    void io_frame(const can_frame& frame, TimePoint now) override;
    void io_bus_event(can::CanBusEvent event, TimePoint now) override;
    void io_cycle(const ptu::PtuCommand& command, bool fresh, TimePoint now) override;
    void io_stop(TimePoint now) override;
    can::IoReport io_report(TimePoint now) override;
    bool send_frame(const can_frame& frame) override { return send(frame); }

    const OdriveSettings settings_;
    std::array<OdriveAxis, ptu::kAxes> axes_;
    bool bus_off_ = false;
};

// Null with `error` for an invalid combination. The real SocketCAN transport.
std::unique_ptr<ptu::PtuDriver> make_odrive_driver(const OdriveSettings& settings, const Clock& clock, std::string& error);
// The same on a given transport (tests, bench).
std::unique_ptr<ptu::PtuDriver> make_odrive_driver(const OdriveSettings& settings,
                                                   std::unique_ptr<can::CanTransport> transport, const Clock& clock,
                                                   std::string& error);

}  // namespace rays::odrive
