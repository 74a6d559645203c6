// SPDX-License-Identifier: Apache-2.0
// Little-endian packing of CAN payloads (CANopen, CiA 301 §7.1: all numbers little-endian; the
// ODrive CAN simple protocol likewise) and frame construction.
#pragma once
#include <linux/can.h>

#include <bit>
#include <cstdint>
#include <cstring>

namespace rays::can {

inline can_frame make_frame(canid_t id, std::uint8_t length) {
    can_frame frame{};
    frame.can_id = id;
    frame.len = length;
    return frame;
}

inline void put_u16(can_frame& frame, int at, std::uint16_t value) {
    frame.data[at] = static_cast<std::uint8_t>(value);
    frame.data[at + 1] = static_cast<std::uint8_t>(value >> 8);
}

inline void put_u32(can_frame& frame, int at, std::uint32_t value) {
    for (int i = 0; i < 4; ++i) frame.data[at + i] = static_cast<std::uint8_t>(value >> (8 * i));
}

inline void put_f32(can_frame& frame, int at, float value) { put_u32(frame, at, std::bit_cast<std::uint32_t>(value)); }

inline std::uint16_t get_u16(const can_frame& frame, int at) {
    return static_cast<std::uint16_t>(frame.data[at] | (frame.data[at + 1] << 8));
}

inline std::uint32_t get_u32(const can_frame& frame, int at) {
    std::uint32_t value = 0;
    for (int i = 3; i >= 0; --i) value = (value << 8) | frame.data[at + i];
    return value;
}

inline float get_f32(const can_frame& frame, int at) { return std::bit_cast<float>(get_u32(frame, at)); }

// Standard (11-bit) data frame id, or 0xFFFFFFFF for extended, remote and error frames.
inline std::uint32_t standard_id(const can_frame& frame) {
    if ((frame.can_id & (CAN_EFF_FLAG | CAN_RTR_FLAG | CAN_ERR_FLAG)) != 0) return 0xFFFFFFFFu;
    return frame.can_id & CAN_SFF_MASK;
}

}  // namespace rays::can
