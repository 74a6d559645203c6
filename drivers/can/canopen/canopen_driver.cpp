// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/canopen_driver.hpp"

#include <numbers>

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"
#include "drivers/can/socket_can_transport.hpp"

namespace rays::canopen {
namespace {

double counts_per_rad(int counts_per_turn) { return counts_per_turn / (2.0 * std::numbers::pi); }

can::CanIoTiming timing_of(const CanopenSettings& s) {
    return {s.cycle_ms / 1000.0, s.command_timeout_s, s.lifecycle_timeout_s};
}

}  // namespace

CanopenDriver::CanopenDriver(const CanopenSettings& settings, std::unique_ptr<can::CanTransport> transport,
                             const Clock& clock)
    : CanIoDriver(std::move(transport), clock, timing_of(settings)),
      settings_(settings),
      axes_{CanopenAxis("pan", settings.pan_node_id, counts_per_rad(settings.pan_counts_per_turn), settings_),
            CanopenAxis("tilt", settings.tilt_node_id, counts_per_rad(settings.tilt_counts_per_turn), settings_)} {}

CanopenDriver::~CanopenDriver() { stop_thread(); }

double CanopenDriver::command_latency_s() const {
    return settings_.cycle_ms / 1000.0;  // write() wakes the I/O thread; at worst the next cycle sends it
}

ptu::DriverStatus CanopenDriver::home(TimePoint now) {
    (void)now;
    if (settings_.absolute_encoders) return ptu::DriverStatus::success();
    return ptu::DriverStatus::failure("canopen: homing (CiA 402 mode 6) is not implemented; use absolute encoders");
}

void CanopenDriver::io_start(TimePoint now) {
    bus_off_ = false;
    next_heartbeat_ = now;
    for (CanopenAxis& axis : axes_) {
        axis.forget_faults();
        axis.start(now);
    }
}

void CanopenDriver::io_frame(const can_frame& frame, TimePoint now) {
    if (bus_off_) {
        bus_off_ = false;  // frames flow again: the controller recovered
        for (CanopenAxis& axis : axes_) axis.start(now);
    }
    for (CanopenAxis& axis : axes_)
        if (axis.on_frame(frame, now, *this)) return;
}

void CanopenDriver::io_bus_event(can::CanBusEvent event, TimePoint now) {
    if (event == can::CanBusEvent::BusOff) {
        bus_off_ = true;
        for (CanopenAxis& axis : axes_) axis.lose("CAN bus-off", now);
    } else if (event == can::CanBusEvent::Restarted && bus_off_) {
        bus_off_ = false;
        for (CanopenAxis& axis : axes_) axis.start(now);
    }
}

void CanopenDriver::io_cycle(const ptu::PtuCommand& command, bool fresh, TimePoint now) {
    (void)fresh;  // RPDOs go out on every cycle and every wake-up anyway
    if (now >= next_heartbeat_ && !bus_off_) {
        can_frame heartbeat = can::make_frame(heartbeat_id(settings_.master_id), 1);
        heartbeat.data[0] = static_cast<std::uint8_t>(NmtState::Operational);
        send(heartbeat);
        next_heartbeat_ = now + std::chrono::milliseconds(settings_.master_heartbeat_ms);
    }
    if (bus_off_) return;
    // A fault on either axis stops both.
    const bool any_fault = axes_[0].faulted() || axes_[1].faulted();
    static const ptu::PtuCommand kStop{};
    const ptu::PtuCommand& applied = any_fault ? kStop : command;
    const bool enable = goal() == can::Goal::Enabled;
    for (std::size_t i = 0; i < ptu::kAxes; ++i) axes_[i].cycle(applied.axes[i], enable, now, *this);
}

void CanopenDriver::io_stop(TimePoint now) {
    (void)now;
    for (CanopenAxis& axis : axes_) axis.stop(*this);
}

can::IoReport CanopenDriver::io_report(TimePoint now) {
    (void)now;
    can::IoReport report;
    report.configured = axes_[0].configured() && axes_[1].configured();
    report.enabled = axes_[0].enabled() && axes_[1].enabled();
    for (std::size_t i = 0; i < ptu::kAxes; ++i) {
        report.state.axes[i] = axes_[i].state();
        if (report.status.ok && !axes_[i].status().ok) report.status = axes_[i].status();
    }
    report.state.stamp = std::max(axes_[0].stamp(), axes_[1].stamp());
    return report;
}

std::unique_ptr<ptu::PtuDriver> make_canopen_driver(const CanopenSettings& settings,
                                                    std::unique_ptr<can::CanTransport> transport, const Clock& clock,
                                                    std::string& error) {
    if (settings.pan_node_id == settings.tilt_node_id) {
        error = "canopen: pan_node_id and tilt_node_id must differ";
        return nullptr;
    }
    if (settings.master_id == settings.pan_node_id || settings.master_id == settings.tilt_node_id) {
        error = "canopen: master_id must differ from the drives' node ids";
        return nullptr;
    }
    if (settings.drive_consumer_timeout_ms <= settings.master_heartbeat_ms) {
        error = "canopen: drive_consumer_timeout_ms must exceed master_heartbeat_ms";
        return nullptr;
    }
    if (settings.drive_heartbeat_timeout_ms <= settings.drive_heartbeat_ms) {
        error = "canopen: drive_heartbeat_timeout_ms must exceed drive_heartbeat_ms";
        return nullptr;
    }
    return std::make_unique<CanopenDriver>(settings, std::move(transport), clock);
}

std::unique_ptr<ptu::PtuDriver> make_canopen_driver(const CanopenSettings& settings, const Clock& clock,
                                                    std::string& error) {
    return make_canopen_driver(settings, std::make_unique<can::SocketCanTransport>(settings.interface), clock, error);
}

}  // namespace rays::canopen
