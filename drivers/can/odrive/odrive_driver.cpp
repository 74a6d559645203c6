// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/odrive/odrive_driver.hpp"

#include <algorithm>
#include <cstdio>
#include <numbers>

#include "drivers/can/socket_can_transport.hpp"

namespace rays::odrive {
namespace {

double turns_per_rad(double ratio) { return ratio / (2.0 * std::numbers::pi); }

can::CanIoTiming timing_of(const OdriveSettings& s) {
    return {s.cycle_ms / 1000.0, s.command_timeout_s, s.lifecycle_timeout_s};
}

}  // namespace

OdriveDriver::OdriveDriver(const OdriveSettings& settings, std::unique_ptr<can::CanTransport> transport,
                           const Clock& clock)
    : CanIoDriver(std::move(transport), clock, timing_of(settings)),
      settings_(settings),
      axes_{OdriveAxis("pan", settings.pan_node_id, turns_per_rad(settings.pan_motor_turns_per_axis_turn), settings_),
            OdriveAxis("tilt", settings.tilt_node_id, turns_per_rad(settings.tilt_motor_turns_per_axis_turn), settings_)} {}

OdriveDriver::~OdriveDriver() { stop_thread(); }

ptu::DriverStatus OdriveDriver::home(TimePoint now) {
    (void)now;
    if (settings_.absolute_encoders) return ptu::DriverStatus::success();
    return ptu::DriverStatus::failure("odrive: homing is not implemented; use absolute encoders");
}

void OdriveDriver::io_start(TimePoint now) {
    bus_off_ = false;
    for (OdriveAxis& axis : axes_) {
        axis.forget_faults();
        axis.start(now);
    }
}

void OdriveDriver::io_frame(const can_frame& frame, TimePoint now) {
    bus_off_ = false;
    for (OdriveAxis& axis : axes_)
        if (axis.on_frame(frame, now)) return;
}

void OdriveDriver::io_bus_event(can::CanBusEvent event, TimePoint now) {
    if (event == can::CanBusEvent::BusOff) {
        bus_off_ = true;
        for (OdriveAxis& axis : axes_) axis.lose("CAN bus-off", now);
    } else if (event == can::CanBusEvent::Restarted) {
        bus_off_ = false;
    }
}

void OdriveDriver::io_cycle(const ptu::PtuCommand& command, bool fresh, TimePoint now) {
    (void)fresh;  // set-points go out on every cycle and every wake-up anyway
    if (bus_off_) return;
    static const ptu::PtuCommand kStop{};
    const bool any_fault = axes_[0].faulted() || axes_[1].faulted();  // a fault on either axis stops both
    const ptu::PtuCommand& applied = any_fault ? kStop : command;
    const bool enable = goal() == can::Goal::Enabled;
    for (std::size_t i = 0; i < ptu::kAxes; ++i) axes_[i].cycle(applied.axes[i], enable, now, *this);
}

void OdriveDriver::io_stop(TimePoint now) {
    (void)now;
    for (OdriveAxis& axis : axes_) axis.stop(*this);
}

can::IoReport OdriveDriver::io_report(TimePoint now) {
    (void)now;
    can::IoReport report;
    report.configured = axes_[0].configured() && axes_[1].configured();
    report.enabled = axes_[0].enabled() && axes_[1].enabled();
    for (std::size_t i = 0; i < ptu::kAxes; ++i) {
        report.state.axes[i] = axes_[i].state();
        if (report.status.ok && !axes_[i].status().ok) report.status = axes_[i].status();
        if (report.waiting.ok && !axes_[i].configured()) {
            char text[120];
            std::snprintf(text, sizeof text, "odrive: %s (node %d): no heartbeat within %.1f s",
                          i == 0 ? "pan" : "tilt", i == 0 ? settings_.pan_node_id : settings_.tilt_node_id,
                          settings_.lifecycle_timeout_s);
            report.waiting = ptu::DriverStatus::failure(text);
        }
    }
    report.state.stamp = std::max(axes_[0].stamp(), axes_[1].stamp());
    return report;
}

std::unique_ptr<ptu::PtuDriver> make_odrive_driver(const OdriveSettings& settings,
                                                   std::unique_ptr<can::CanTransport> transport, const Clock& clock,
                                                   std::string& error) {
    if (settings.pan_node_id == settings.tilt_node_id) {
        error = "odrive: pan_node_id and tilt_node_id must differ";
        return nullptr;
    }
    if (settings.heartbeat_timeout_ms <= settings.cycle_ms) {
        error = "odrive: heartbeat_timeout_ms must exceed cycle_ms";
        return nullptr;
    }
    return std::make_unique<OdriveDriver>(settings, std::move(transport), clock);
}

std::unique_ptr<ptu::PtuDriver> make_odrive_driver(const OdriveSettings& settings, const Clock& clock, std::string& error) {
    return make_odrive_driver(settings, std::make_unique<can::SocketCanTransport>(settings.interface), clock, error);
}

}  // namespace rays::odrive
