// SPDX-License-Identifier: Apache-2.0
// CANopen identifiers and object indices used here (CiA 301 v4.2, CiA 402-2 v4.1).
#pragma once
#include <cstdint>

namespace rays::canopen {

// Pre-defined connection set, CiA 301 §7.3.5 (COB-ID = function code + node id).
constexpr std::uint32_t kNmtId = 0x000;
constexpr std::uint32_t emcy_id(int node) { return 0x080u + static_cast<std::uint32_t>(node); }
constexpr std::uint32_t tpdo_id(int pdo, int node) { return 0x180u + 0x100u * static_cast<std::uint32_t>(pdo - 1) + static_cast<std::uint32_t>(node); }
constexpr std::uint32_t rpdo_id(int pdo, int node) { return 0x200u + 0x100u * static_cast<std::uint32_t>(pdo - 1) + static_cast<std::uint32_t>(node); }
constexpr std::uint32_t sdo_tx_id(int node) { return 0x580u + static_cast<std::uint32_t>(node); }  // server → client
constexpr std::uint32_t sdo_rx_id(int node) { return 0x600u + static_cast<std::uint32_t>(node); }  // client → server
constexpr std::uint32_t heartbeat_id(int node) { return 0x700u + static_cast<std::uint32_t>(node); }

// NMT node control command specifiers, CiA 301 §7.2.8.3.1.
enum class Nmt : std::uint8_t { Start = 0x01, Stop = 0x02, PreOperational = 0x80, ResetNode = 0x81, ResetCommunication = 0x82 };

// NMT states in the heartbeat message, CiA 301 §7.2.8.3.2.2.
enum class NmtState : std::uint8_t { BootUp = 0x00, Stopped = 0x04, Operational = 0x05, PreOperational = 0x7F };

// PDO communication/mapping parameters, CiA 301 §7.5.2.35-38: COB-ID bit 31 = PDO not valid.
constexpr std::uint32_t kPdoInvalid = 0x80000000u;
constexpr std::uint8_t kTransmissionEventDriven = 0xFF;  // manufacturer-specific event (event timer)
constexpr std::uint32_t mapping(std::uint16_t index, std::uint8_t sub, std::uint8_t bits) {
    return (static_cast<std::uint32_t>(index) << 16) | (static_cast<std::uint32_t>(sub) << 8) | bits;
}

namespace od {
constexpr std::uint16_t kConsumerHeartbeat = 0x1016;  // sub n: node id << 16 | time ms (CiA 301 §7.5.2.32)
constexpr std::uint16_t kProducerHeartbeat = 0x1017;  // u16 ms (§7.5.2.33)
constexpr std::uint16_t kRpdoComm = 0x1400, kRpdoMap = 0x1600, kTpdoComm = 0x1800, kTpdoMap = 0x1A00;
// CiA 402-2 objects.
constexpr std::uint16_t kAbortConnection = 0x6007;  // i16: action on communication loss
constexpr std::uint16_t kControlword = 0x6040, kStatusword = 0x6041;
constexpr std::uint16_t kModesOfOperation = 0x6060, kModesDisplay = 0x6061;  // i8
constexpr std::uint16_t kPositionActual = 0x6064, kVelocityActual = 0x606C;  // i32
constexpr std::uint16_t kTargetPosition = 0x607A, kMaxProfileVelocity = 0x607F;
constexpr std::uint16_t kProfileVelocity = 0x6081, kProfileAcceleration = 0x6083, kProfileDeceleration = 0x6084;
constexpr std::uint16_t kQuickStopDeceleration = 0x6085, kTargetVelocity = 0x60FF;
}  // namespace od

// Modes of operation 0x6060, CiA 402-2 §6.2.3 (Table 31).
constexpr std::int8_t kProfilePosition = 1, kProfileVelocity = 3;
// Abort connection option code 0x6007, CiA 402-2 §6.2.6.
constexpr std::int16_t kAbortFault = 1, kAbortDisableVoltage = 2, kAbortQuickStop = 3;

}  // namespace rays::canopen
