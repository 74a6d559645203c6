// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/sim/cia402_sim_drive.hpp"

#include <algorithm>
#include <cmath>

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"
#include "drivers/can/canopen/sdo.hpp"

namespace rays::canopen {
namespace {

using ptu::AxisCommand;
using ptu::CommandMode;

}  // namespace

Cia402SimDrive::Cia402SimDrive(const Cia402SimConfig& config) : config_(config), axis_(config.dynamics) {
    const auto node = static_cast<std::uint32_t>(config.node);
    dictionary_ = {
        {0x1000, 0, 4, false, 0x00020192},  // device type: CiA 402 servo drive
        {od::kConsumerHeartbeat, 0, 1, false, 1},
        {od::kConsumerHeartbeat, 1, 4, true, 0},
        {od::kProducerHeartbeat, 0, 2, true, 0},
        {od::kAbortConnection, 0, 2, true, static_cast<std::uint32_t>(kAbortFault)},
        {od::kControlword, 0, 2, true, 0},
        {od::kStatusword, 0, 2, false, 0},
        {od::kModesOfOperation, 0, 1, true, 0},
        {od::kModesDisplay, 0, 1, false, 0},
        {od::kPositionActual, 0, 4, false, 0},
        {od::kVelocityActual, 0, 4, false, 0},
        {od::kTargetPosition, 0, 4, true, 0},
        {od::kMaxProfileVelocity, 0, 4, true, 0},
        {od::kProfileVelocity, 0, 4, true, 0},
        {od::kProfileAcceleration, 0, 4, true, 0},
        {od::kProfileDeceleration, 0, 4, true, 0},
        {od::kQuickStopDeceleration, 0, 4, true, 0},
        {od::kTargetVelocity, 0, 4, true, 0},
    };
    for (std::uint16_t k = 0; k < 2; ++k) {
        dictionary_.push_back({static_cast<std::uint16_t>(od::kRpdoComm + k), 1, 4, true, rpdo_id(k + 1, config.node)});
        dictionary_.push_back({static_cast<std::uint16_t>(od::kRpdoComm + k), 2, 1, true, 0xFF});
        dictionary_.push_back({static_cast<std::uint16_t>(od::kTpdoComm + k), 1, 4, true, tpdo_id(k + 1, config.node) | kPdoInvalid});
        dictionary_.push_back({static_cast<std::uint16_t>(od::kTpdoComm + k), 2, 1, true, 0xFF});
        dictionary_.push_back({static_cast<std::uint16_t>(od::kTpdoComm + k), 5, 2, true, 0});
        for (std::uint8_t sub = 0; sub <= 8; ++sub) {
            dictionary_.push_back({static_cast<std::uint16_t>(od::kRpdoMap + k), sub, static_cast<std::uint8_t>(sub == 0 ? 1 : 4), true, 0});
            dictionary_.push_back({static_cast<std::uint16_t>(od::kTpdoMap + k), sub, static_cast<std::uint8_t>(sub == 0 ? 1 : 4), true, 0});
        }
    }
    (void)node;
    received_.reserve(config.record_capacity);
}

Cia402SimDrive::Entry* Cia402SimDrive::find(std::uint16_t index, std::uint8_t sub) {
    for (Entry& entry : dictionary_)
        if (entry.index == index && entry.sub == sub) return &entry;
    return nullptr;
}

const Cia402SimDrive::Entry* Cia402SimDrive::find(std::uint16_t index, std::uint8_t sub) const {
    return const_cast<Cia402SimDrive*>(this)->find(index, sub);
}

std::uint32_t Cia402SimDrive::get(std::uint16_t index, std::uint8_t sub) const {
    const Entry* entry = find(index, sub);
    return entry != nullptr ? entry->value : 0;
}

void Cia402SimDrive::set(std::uint16_t index, std::uint8_t sub, std::uint32_t value) {
    if (Entry* entry = find(index, sub)) entry->value = value;
}

void Cia402SimDrive::enter(DriveState state, TimePoint now) {
    if (state != DriveState::OperationEnabled && state_ == DriveState::OperationEnabled) axis_.halt(now);
    if (state == DriveState::Fault) axis_.halt(now);
    state_ = state;
    acknowledged_ = false;
}

std::uint16_t Cia402SimDrive::statusword() const {
    std::uint16_t word = 0;
    switch (state_) {
        case DriveState::NotReadyToSwitchOn: word = 0x0000; break;
        case DriveState::SwitchOnDisabled: word = 0x0040; break;
        case DriveState::ReadyToSwitchOn: word = 0x0031; break;
        case DriveState::SwitchedOn: word = 0x0033; break;
        case DriveState::OperationEnabled: word = 0x0037; break;
        case DriveState::QuickStopActive: word = 0x0017; break;
        case DriveState::FaultReactionActive: word = 0x001F; break;
        case DriveState::Fault: word = 0x0018; break;
    }
    if (acknowledged_) word |= sw::kSetPointAcknowledge;
    return static_cast<std::uint16_t>(word | 0x0200);  // bit 9 remote
}

void Cia402SimDrive::on_controlword(std::uint16_t controlword, TimePoint now) {
    const bool reset_edge = (controlword & cw::kFaultReset) != 0 && (last_controlword_ & cw::kFaultReset) == 0;
    const std::uint16_t previous = last_controlword_;
    last_controlword_ = controlword;
    set(od::kControlword, 0, controlword);
    if (state_ == DriveState::Fault) {
        if (reset_edge && !fault_condition_) enter(DriveState::SwitchOnDisabled, now);  // transition 15
        return;
    }
    if ((controlword & cw::kFaultReset) != 0) return;
    // CiA 402-2 Table 27 command coding.
    if ((controlword & 0x02) == 0) enter(DriveState::SwitchOnDisabled, now);                    // disable voltage
    else if ((controlword & 0x06) == 0x02) enter(DriveState::SwitchOnDisabled, now);            // quick stop (ends there)
    else if ((controlword & 0x0F) == 0x06) enter(DriveState::ReadyToSwitchOn, now);             // shutdown
    else if ((controlword & 0x0F) == 0x07) {                                                    // switch on
        if (state_ == DriveState::ReadyToSwitchOn || state_ == DriveState::OperationEnabled) enter(DriveState::SwitchedOn, now);
    } else if ((controlword & 0x0F) == 0x0F) {                                                  // enable operation
        if (state_ == DriveState::SwitchedOn || state_ == DriveState::ReadyToSwitchOn) enter(DriveState::OperationEnabled, now);
    }
    if (state_ != DriveState::OperationEnabled) return;
    const auto mode = static_cast<std::int8_t>(get(od::kModesOfOperation, 0));
    if (mode == kProfilePosition) {
        const bool rising = (controlword & cw::kNewSetPoint) != 0 && (previous & cw::kNewSetPoint) == 0;
        if (rising && !acknowledged_) {
            const auto target = static_cast<std::int32_t>(get(od::kTargetPosition, 0));
            // The profile velocity (0x6081), bounded by the max profile velocity (0x607F).
            const auto profile = std::min(get(od::kProfileVelocity, 0), get(od::kMaxProfileVelocity, 0));
            axis_.set_position_velocity(profile / config_.counts_per_rad);
            axis_.command(AxisCommand{CommandMode::Position, target / config_.counts_per_rad}, now);
            acknowledged_ = true;
        } else if ((controlword & cw::kNewSetPoint) == 0) {
            acknowledged_ = false;
        }
    }
}

void Cia402SimDrive::apply_motion(TimePoint now) {
    if (state_ != DriveState::OperationEnabled) return;
    const auto mode = static_cast<std::int8_t>(get(od::kModesOfOperation, 0));
    set(od::kModesDisplay, 0, static_cast<std::uint8_t>(mode));
    if (mode == kProfileVelocity) {
        const auto target = static_cast<std::int32_t>(get(od::kTargetVelocity, 0));
        axis_.command(AxisCommand{CommandMode::Velocity, target / config_.counts_per_rad}, now);
    }
}

void Cia402SimDrive::on_rpdo(int pdo, const can_frame& frame, TimePoint now) {
    const auto map = static_cast<std::uint16_t>(od::kRpdoMap + pdo);
    const auto count = static_cast<std::uint8_t>(get(map, 0));
    int at = 0;
    std::uint16_t controlword = 0;
    bool has_controlword = false;
    for (std::uint8_t sub = 1; sub <= count; ++sub) {  // byte-aligned entries only
        const std::uint32_t entry = get(map, sub);
        const auto index = static_cast<std::uint16_t>(entry >> 16);
        const auto bytes = static_cast<int>((entry & 0xFF) / 8);
        if (at + bytes > frame.len) return;  // too short: CiA 301 says ignore (EMCY 0x8210)
        std::uint32_t value = 0;
        for (int i = bytes - 1; i >= 0; --i) value = (value << 8) | frame.data[at + i];
        at += bytes;
        if (index == od::kControlword) {
            controlword = static_cast<std::uint16_t>(value);
            has_controlword = true;
        } else {
            set(index, static_cast<std::uint8_t>(entry >> 8), value);
        }
    }
    if (has_controlword) on_controlword(controlword, now);  // after the targets it carries
    apply_motion(now);
}

void Cia402SimDrive::on_sdo(const can_frame& frame, can::FrameSink& bus) {
    const std::uint8_t command = frame.data[0];
    const std::uint16_t index = can::get_u16(frame, 1);
    const std::uint8_t sub = frame.data[3];
    if (abort_index_ != 0 && index == abort_index_) {
        bus.send_frame(sdo_abort(config_.node, index, sub, abort_code_));
        return;
    }
    Entry* entry = find(index, sub);
    if (entry == nullptr) {
        const bool object = find(index, 0) != nullptr;
        bus.send_frame(sdo_abort(config_.node, index, sub, object ? sdo_abort_code::kNoSubIndex : sdo_abort_code::kNoObject));
        return;
    }
    if (command == 0x40) {
        bus.send_frame(sdo_upload_reply(config_.node, index, sub, entry->value, entry->size));
        return;
    }
    if ((command & 0xE3) != 0x23) {
        bus.send_frame(sdo_abort(config_.node, index, sub, sdo_abort_code::kBadCommand));
        return;
    }
    const int size = 4 - ((command >> 2) & 0x3);
    if (!entry->writable) {
        bus.send_frame(sdo_abort(config_.node, index, sub, sdo_abort_code::kReadOnly));
        return;
    }
    if (size != entry->size) {
        bus.send_frame(sdo_abort(config_.node, index, sub, sdo_abort_code::kLengthMismatch));
        return;
    }
    const std::uint32_t value = can::get_u32(frame, 4);
    if (index == od::kControlword) {
        on_controlword(static_cast<std::uint16_t>(value), last_master_heartbeat_);
    } else {
        entry->value = value;
        if (index == od::kConsumerHeartbeat) consumer_active_ = false;  // active from the next heartbeat
    }
    bus.send_frame(sdo_download_ack(config_.node, index, sub));
}

void Cia402SimDrive::on_frame(const can_frame& frame, TimePoint now, can::FrameSink& bus) {
    std::lock_guard lock(mutex_);
    const std::uint32_t id = can::standard_id(frame);
    const std::uint32_t consumer = get(od::kConsumerHeartbeat, 1);
    const int watched = static_cast<int>((consumer >> 16) & 0x7F);
    const bool mine = id == kNmtId || id == sdo_rx_id(config_.node) || (watched != 0 && id == heartbeat_id(watched)) ||
                      id == get(od::kRpdoComm, 1) || id == get(od::kRpdoComm + 1, 1);
    if (!mine) return;
    if (received_.size() < received_.capacity()) received_.push_back({now, frame});
    axis_.advance(now);
    if (id == kNmtId && frame.len >= 2 && (frame.data[1] == 0 || frame.data[1] == config_.node)) {
        switch (static_cast<Nmt>(frame.data[0])) {
            case Nmt::Start: nmt_ = static_cast<std::uint8_t>(NmtState::Operational); break;
            case Nmt::Stop: nmt_ = static_cast<std::uint8_t>(NmtState::Stopped); break;
            case Nmt::PreOperational: nmt_ = static_cast<std::uint8_t>(NmtState::PreOperational); break;
            default: booted_ = false; break;  // resets: boot-up again
        }
    } else if (id == sdo_rx_id(config_.node) && frame.len == 8) {
        if (!muted_) on_sdo(frame, bus);
    } else if (watched != 0 && id == heartbeat_id(watched)) {
        last_master_heartbeat_ = now;
        consumer_active_ = true;  // CiA 301 §7.2.8.2.2.2: monitoring starts with the first heartbeat
    } else if (nmt_ == static_cast<std::uint8_t>(NmtState::Operational)) {
        for (int k = 0; k < 2; ++k)
            if (id == get(static_cast<std::uint16_t>(od::kRpdoComm + k), 1)) on_rpdo(k, frame, now);
    }
}

void Cia402SimDrive::send_tpdo(int pdo, can::FrameSink& bus) {
    const auto map = static_cast<std::uint16_t>(od::kTpdoMap + pdo);
    can_frame frame = can::make_frame(get(static_cast<std::uint16_t>(od::kTpdoComm + pdo), 1) & CAN_SFF_MASK, 0);
    const auto count = static_cast<std::uint8_t>(get(map, 0));
    for (std::uint8_t sub = 1; sub <= count; ++sub) {
        const std::uint32_t entry = get(map, sub);
        const auto index = static_cast<std::uint16_t>(entry >> 16);
        const auto bytes = static_cast<int>((entry & 0xFF) / 8);
        const std::uint32_t value = index == od::kStatusword ? statusword() : get(index, static_cast<std::uint8_t>(entry >> 8));
        for (int i = 0; i < bytes && frame.len < 8; ++i) frame.data[frame.len++] = static_cast<std::uint8_t>(value >> (8 * i));
    }
    bus.send_frame(frame);
}

void Cia402SimDrive::emergency(std::uint16_t code, can::FrameSink& bus) {
    can_frame frame = can::make_frame(emcy_id(config_.node), 8);
    can::put_u16(frame, 0, code);
    frame.data[2] = 0x01;  // error register: generic error
    bus.send_frame(frame);
}

void Cia402SimDrive::tick(TimePoint now, can::FrameSink& bus) {
    std::lock_guard lock(mutex_);
    axis_.advance(now);
    set(od::kPositionActual, 0, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(axis_.position() * config_.counts_per_rad))));
    set(od::kVelocityActual, 0, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(axis_.velocity() * config_.counts_per_rad))));
    set(od::kStatusword, 0, statusword());
    if (!booted_) {  // CiA 301 §7.2.8.3.2.1: boot-up message, then pre-operational
        booted_ = true;
        nmt_ = static_cast<std::uint8_t>(NmtState::PreOperational);
        if (!muted_) bus.send_frame(can::make_frame(heartbeat_id(config_.node), 1));
        next_heartbeat_ = now;
    }
    const std::uint32_t consumer = get(od::kConsumerHeartbeat, 1);
    const auto consumer_time = std::chrono::milliseconds(consumer & 0xFFFF);
    if (consumer_active_ && consumer_time.count() > 0 && now - last_master_heartbeat_ > consumer_time) {
        consumer_active_ = false;
        ++communication_losses_;
        if (!muted_) emergency(0x8130, bus);  // heartbeat error
        switch (static_cast<std::int16_t>(get(od::kAbortConnection, 0))) {  // CiA 402-2 §6.2.6
            case kAbortFault: enter(DriveState::Fault, now); break;
            case kAbortDisableVoltage: enter(DriveState::SwitchOnDisabled, now); break;
            case kAbortQuickStop: enter(DriveState::SwitchOnDisabled, now); break;  // after the quick-stop ramp
            default: break;
        }
    }
    if (pending_emcy_ != 0) {
        if (!muted_) emergency(pending_emcy_, bus);
        pending_emcy_ = 0;
    }
    if (muted_) return;
    const auto period = std::chrono::milliseconds(get(od::kProducerHeartbeat, 0));
    if (period.count() > 0 && !heartbeat_stopped_ && now >= next_heartbeat_) {
        can_frame frame = can::make_frame(heartbeat_id(config_.node), 1);
        frame.data[0] = nmt_;
        bus.send_frame(frame);
        next_heartbeat_ = now + period;
    }
    if (nmt_ != static_cast<std::uint8_t>(NmtState::Operational)) return;
    for (int k = 0; k < 2; ++k) {
        const auto comm = static_cast<std::uint16_t>(od::kTpdoComm + k);
        const auto timer = std::chrono::milliseconds(get(comm, 5));
        if ((get(comm, 1) & kPdoInvalid) != 0 || timer.count() == 0 || now < next_tpdo_[static_cast<std::size_t>(k)]) continue;
        send_tpdo(k, bus);
        next_tpdo_[static_cast<std::size_t>(k)] = now + timer;
    }
}

double Cia402SimDrive::position_rad() const { std::lock_guard lock(mutex_); return axis_.position(); }
double Cia402SimDrive::velocity_rad_s() const { std::lock_guard lock(mutex_); return axis_.velocity(); }
DriveState Cia402SimDrive::state() const { std::lock_guard lock(mutex_); return state_; }
std::uint8_t Cia402SimDrive::nmt_state() const { std::lock_guard lock(mutex_); return nmt_; }
std::uint32_t Cia402SimDrive::object(std::uint16_t index, std::uint8_t sub) const { std::lock_guard lock(mutex_); return get(index, sub); }
std::vector<ReceivedFrame> Cia402SimDrive::received() const { std::lock_guard lock(mutex_); return received_; }
int Cia402SimDrive::communication_losses() const { std::lock_guard lock(mutex_); return communication_losses_; }

void Cia402SimDrive::inject_fault(std::uint16_t emcy_code) {
    std::lock_guard lock(mutex_);
    fault_condition_ = true;
    enter(DriveState::Fault, last_master_heartbeat_);
    pending_emcy_ = emcy_code;
}

void Cia402SimDrive::clear_fault() { std::lock_guard lock(mutex_); fault_condition_ = false; }
void Cia402SimDrive::stop_heartbeat(bool stopped) { std::lock_guard lock(mutex_); heartbeat_stopped_ = stopped; }
void Cia402SimDrive::abort_sdo(std::uint16_t index, std::uint32_t code) {
    std::lock_guard lock(mutex_);
    abort_index_ = index;
    abort_code_ = code;
}
void Cia402SimDrive::mute(bool muted) { std::lock_guard lock(mutex_); muted_ = muted; }

}  // namespace rays::canopen
