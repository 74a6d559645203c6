// SPDX-License-Identifier: Apache-2.0
// The CiA 402 drive state machine seen through the statusword and driven by the controlword,
// CiA 402-2 §6.1 (Figure 4: states and transitions; Table 30: statusword state bits; Table 27:
// controlword commands).
#pragma once
#include <cstdint>

namespace rays::canopen {

enum class DriveState {
    NotReadyToSwitchOn,
    SwitchOnDisabled,
    ReadyToSwitchOn,
    SwitchedOn,
    OperationEnabled,
    QuickStopActive,
    FaultReactionActive,
    Fault,
};

DriveState decode_statusword(std::uint16_t statusword);
const char* drive_state_name(DriveState state);

namespace cw {
constexpr std::uint16_t kDisableVoltage = 0x0000, kQuickStop = 0x0002, kShutdown = 0x0006;
constexpr std::uint16_t kSwitchOn = 0x0007, kEnableOperation = 0x000F, kFaultReset = 0x0080;
// Profile position mode bits, CiA 402-2 §12.3.1 (Table 130).
constexpr std::uint16_t kNewSetPoint = 1u << 4, kChangeSetImmediately = 1u << 5;
}  // namespace cw

namespace sw {
constexpr std::uint16_t kFault = 1u << 3, kSetPointAcknowledge = 1u << 12;  // bit 12 in pp (Table 131)
}

// The controlword that takes a drive from `state` one step toward Operation enabled (transitions
// 2, 3, 4 of Figure 4; 15 fault reset needs a rising edge of bit 7, see CanopenAxis).
std::uint16_t controlword_toward_enabled(DriveState state);

}  // namespace rays::canopen
