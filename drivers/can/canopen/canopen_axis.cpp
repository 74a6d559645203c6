// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/canopen_axis.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"

namespace rays::canopen {
namespace {

TimePoint::duration ms(int milliseconds) { return std::chrono::milliseconds(milliseconds); }

can_frame nmt_frame(Nmt command, int node) {
    can_frame frame = can::make_frame(kNmtId, 2);
    frame.data[0] = static_cast<std::uint8_t>(command);
    frame.data[1] = static_cast<std::uint8_t>(node);
    return frame;
}

constexpr double kFaultResetInterval_s = 0.5;

}  // namespace

CanopenAxis::CanopenAxis(const char* label, int node, double counts_per_rad, const CanopenSettings& settings)
    : label_(label),
      node_(node),
      counts_per_rad_(counts_per_rad),
      plan_(configuration_plan(settings, node, counts_per_rad)),
      sdo_timeout_(ms(settings.sdo_timeout_ms)),
      heartbeat_timeout_(ms(settings.drive_heartbeat_timeout_ms)),
      absolute_(settings.absolute_encoders) {}

void CanopenAxis::start(TimePoint now) {
    phase_ = Phase::Configuring;
    step_ = 0;
    sdo_pending_ = false;
    nmt_pending_ = true;
    last_heartbeat_ = now;
    setpoint_requested_ = setpoint_valid_ = false;
    last_controlword_ = 0;
}

void CanopenAxis::forget_faults() {
    status_ = ptu::DriverStatus::success();
    drive_fault_ = false;
    backoff_s_ = 0.5;
}

void CanopenAxis::fail(TimePoint now, const char* format, ...) {
    char text[120];
    int used = std::snprintf(text, sizeof text, "canopen: %s (node %d): ", label_, node_);
    va_list args;
    va_start(args, format);
    std::vsnprintf(text + used, sizeof text - static_cast<std::size_t>(used), format, args);
    va_end(args);
    status_ = ptu::DriverStatus::failure(text);
    phase_ = Phase::Backoff;
    sdo_pending_ = false;
    retry_at_ = now + std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(backoff_s_));
    backoff_s_ = std::min(backoff_s_ * 2.0, 8.0);
}

void CanopenAxis::lose(const char* why, TimePoint now) { fail(now, "%s", why); }

bool CanopenAxis::on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus) {
    const std::uint32_t id = can::standard_id(frame);
    if (id == sdo_tx_id(node_)) {
        if (phase_ == Phase::Configuring && sdo_pending_) on_sdo_reply(frame, now, bus);
    } else if (id == heartbeat_id(node_) && frame.len >= 1) {
        last_heartbeat_ = now;
        // A boot-up message from a configured drive: it was reset and lost its configuration.
        if (frame.data[0] == static_cast<std::uint8_t>(NmtState::BootUp) &&
            (phase_ == Phase::Configured || phase_ == Phase::Operational))
            fail(now, "drive rebooted (boot-up message); configuring it again");
    } else if (id == tpdo_id(1, node_) && frame.len >= 6) {
        statusword_ = can::get_u16(frame, 0);
        position_counts_ = static_cast<std::int32_t>(can::get_u32(frame, 2));
        state_ = decode_statusword(statusword_);
        stamp_ = now;
        const bool fault = state_ == DriveState::Fault || state_ == DriveState::FaultReactionActive;
        if (fault && phase_ == Phase::Operational && !drive_fault_) {
            drive_fault_ = true;
            char text[120];
            std::snprintf(text, sizeof text, "canopen: %s (node %d): drive fault (statusword 0x%04X, EMCY 0x%04X)",
                          label_, node_, statusword_, last_emcy_);
            status_ = ptu::DriverStatus::failure(text);
        } else if (!fault && drive_fault_) {
            drive_fault_ = false;
            status_ = ptu::DriverStatus::success();
        }
    } else if (id == tpdo_id(2, node_) && frame.len >= 4) {
        velocity_counts_ = static_cast<std::int32_t>(can::get_u32(frame, 0));
    } else if (id == emcy_id(node_) && frame.len >= 2) {
        last_emcy_ = can::get_u16(frame, 0);  // CiA 301 §7.2.7.3.1: error code, 0 = error reset
    } else {
        return false;
    }
    return true;
}

void CanopenAxis::send_sdo(TimePoint now, can::FrameSink& bus) {
    bus.send_frame(sdo_request_frame(node_, plan_.steps[step_]));
    sdo_pending_ = true;
    sdo_deadline_ = now + sdo_timeout_;
}

void CanopenAxis::on_sdo_reply(const can_frame& frame, TimePoint now, can::FrameSink& bus) {
    const SdoRequest& request = plan_.steps[step_];
    const SdoReply reply = parse_sdo_reply(frame);
    if (reply.index != request.index || reply.sub != request.sub) return;  // not the answer to this request
    if (reply.kind == SdoReplyKind::Aborted) {
        fail(now, "SDO abort 0x%08X (%s) %s 0x%04X:%02X", reply.value, sdo_abort_text(reply.value),
             request.upload ? "reading" : "writing", request.index, request.sub);
        return;
    }
    const SdoReplyKind expected = request.upload ? SdoReplyKind::Uploaded : SdoReplyKind::Downloaded;
    if (reply.kind != expected) {
        fail(now, "unexpected SDO reply to 0x%04X:%02X", request.index, request.sub);
        return;
    }
    if (request.upload && request.index == od::kStatusword) {
        statusword_ = static_cast<std::uint16_t>(reply.value);
        state_ = decode_statusword(statusword_);
    }
    sdo_pending_ = false;
    if (++step_ < plan_.count) {
        send_sdo(now, bus);
        return;
    }
    phase_ = Phase::Configured;
    status_ = ptu::DriverStatus::success();
    drive_fault_ = false;
    backoff_s_ = 0.5;
    last_heartbeat_ = now;
}

void CanopenAxis::cycle(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus) {
    if ((phase_ == Phase::Configured || phase_ == Phase::Operational) && now - last_heartbeat_ > heartbeat_timeout_)
        fail(now, "heartbeat lost (none for %lld ms)",
             static_cast<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(now - last_heartbeat_).count()));
    switch (phase_) {
        case Phase::Backoff:
            if (now >= retry_at_) start(now);
            break;
        case Phase::Configuring:
            if (nmt_pending_) {
                bus.send_frame(nmt_frame(Nmt::PreOperational, node_));
                nmt_pending_ = false;
            }
            if (!sdo_pending_) send_sdo(now, bus);
            else if (now > sdo_deadline_)
                fail(now, "no SDO reply to 0x%04X:%02X within %lld ms", plan_.steps[step_].index, plan_.steps[step_].sub,
                     static_cast<long long>(std::chrono::duration_cast<std::chrono::milliseconds>(sdo_timeout_).count()));
            break;
        case Phase::Configured:
            if (enable) {
                bus.send_frame(nmt_frame(Nmt::Start, node_));  // CiA 301 §7.2.8.3.1.1: PDOs from now on
                phase_ = Phase::Operational;
            }
            break;
        case Phase::Operational:
            send_rpdo(command, enable, now, bus);
            break;
    }
}

std::int32_t CanopenAxis::to_counts(double value) const {
    const double counts = std::isfinite(value) ? std::round(value * counts_per_rad_) : 0.0;
    return static_cast<std::int32_t>(std::clamp(counts, static_cast<double>(std::numeric_limits<std::int32_t>::min()),
                                                static_cast<double>(std::numeric_limits<std::int32_t>::max())));
}

std::uint16_t CanopenAxis::position_handshake(std::int32_t target, std::int32_t& send) {
    // CiA 402-2 §12.2 (Figure 64): raise bit 4 with the target, wait for bit 12, drop bit 4, wait for
    // bit 12 to drop; bit 5 (change set immediately) makes each new set-point replace the last.
    const bool acknowledged = (statusword_ & sw::kSetPointAcknowledge) != 0;
    if (setpoint_requested_ && acknowledged) {
        setpoint_requested_ = false;
        setpoint_acked_ = setpoint_sent_;
        setpoint_valid_ = true;
    }
    if (!setpoint_requested_ && !acknowledged && (!setpoint_valid_ || target != setpoint_acked_)) {
        setpoint_requested_ = true;
        setpoint_sent_ = target;
    }
    send = setpoint_requested_ ? setpoint_sent_ : setpoint_acked_;
    return cw::kChangeSetImmediately | (setpoint_requested_ ? cw::kNewSetPoint : 0);
}

void CanopenAxis::send_rpdo(const ptu::AxisCommand& command, bool enable, TimePoint now, can::FrameSink& bus) {
    std::uint16_t controlword = cw::kDisableVoltage;
    if (!enable) {
        controlword = cw::kShutdown;
    } else if (state_ == DriveState::Fault) {
        // Fault reset on a rising edge of bit 7, one try per interval.
        if (now >= next_reset_ && (last_controlword_ & cw::kFaultReset) == 0) {
            controlword = cw::kFaultReset;
            next_reset_ = now + std::chrono::duration_cast<TimePoint::duration>(
                                    std::chrono::duration<double>(kFaultResetInterval_s));
        }
    } else if (state_ != DriveState::FaultReactionActive) {
        controlword = controlword_toward_enabled(state_);
    }
    last_controlword_ = controlword;
    const bool moving = enable && state_ == DriveState::OperationEnabled && !faulted();
    can_frame frame{};
    if (moving && command.mode == ptu::CommandMode::Position) {
        std::int32_t target = 0;
        controlword = static_cast<std::uint16_t>(controlword | position_handshake(to_counts(command.value), target));
        frame = can::make_frame(rpdo_id(2, node_), 7);
        frame.data[2] = static_cast<std::uint8_t>(kProfilePosition);
        can::put_u32(frame, 3, static_cast<std::uint32_t>(target));
    } else {
        setpoint_requested_ = setpoint_valid_ = false;
        const std::int32_t velocity = moving ? to_counts(command.value) : 0;
        frame = can::make_frame(rpdo_id(1, node_), 7);
        frame.data[2] = static_cast<std::uint8_t>(kProfileVelocity);
        can::put_u32(frame, 3, static_cast<std::uint32_t>(velocity));
    }
    can::put_u16(frame, 0, controlword);
    bus.send_frame(frame);
}

void CanopenAxis::stop(can::FrameSink& bus) {
    if (phase_ == Phase::Operational) {
        can_frame frame = can::make_frame(rpdo_id(1, node_), 7);
        can::put_u16(frame, 0, cw::kQuickStop);
        frame.data[2] = static_cast<std::uint8_t>(kProfileVelocity);
        bus.send_frame(frame);
    }
    bus.send_frame(nmt_frame(Nmt::PreOperational, node_));
    phase_ = Phase::Backoff;
}

ptu::AxisState CanopenAxis::state() const {
    return ptu::AxisState{position_counts_ / counts_per_rad_, velocity_counts_ / counts_per_rad_, enabled(), faulted(),
                          absolute_};
}

}  // namespace rays::canopen
