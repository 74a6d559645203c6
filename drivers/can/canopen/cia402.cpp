// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/cia402.hpp"

namespace rays::canopen {

DriveState decode_statusword(std::uint16_t statusword) {
    // Table 30: bits 0-3, 5, 6 (mask 0x6F; 0x4F where bit 5 is "x").
    switch (statusword & 0x4F) {
        case 0x00: return DriveState::NotReadyToSwitchOn;
        case 0x40: return DriveState::SwitchOnDisabled;
        case 0x0F: return DriveState::FaultReactionActive;
        case 0x08: return DriveState::Fault;
        default: break;
    }
    switch (statusword & 0x6F) {
        case 0x21: return DriveState::ReadyToSwitchOn;
        case 0x23: return DriveState::SwitchedOn;
        case 0x27: return DriveState::OperationEnabled;
        case 0x07: return DriveState::QuickStopActive;
        default: return DriveState::NotReadyToSwitchOn;
    }
}

const char* drive_state_name(DriveState state) {
    switch (state) {
        case DriveState::NotReadyToSwitchOn: return "not ready to switch on";
        case DriveState::SwitchOnDisabled: return "switch on disabled";
        case DriveState::ReadyToSwitchOn: return "ready to switch on";
        case DriveState::SwitchedOn: return "switched on";
        case DriveState::OperationEnabled: return "operation enabled";
        case DriveState::QuickStopActive: return "quick stop active";
        case DriveState::FaultReactionActive: return "fault reaction active";
        case DriveState::Fault: return "fault";
    }
    return "?";
}

std::uint16_t controlword_toward_enabled(DriveState state) {
    switch (state) {
        case DriveState::SwitchOnDisabled: return cw::kShutdown;         // transition 2
        case DriveState::ReadyToSwitchOn: return cw::kSwitchOn;          // transition 3
        case DriveState::SwitchedOn: return cw::kEnableOperation;        // transition 4
        case DriveState::OperationEnabled: return cw::kEnableOperation;  // stay
        case DriveState::QuickStopActive: return cw::kDisableVoltage;    // transition 12
        default: return cw::kDisableVoltage;
    }
}

}  // namespace rays::canopen
