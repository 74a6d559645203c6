// SPDX-License-Identifier: Apache-2.0
// SDO expedited transfers, CiA 301 §7.2.4.3: download (write ≤ 4 bytes) and upload (read) requests,
// their replies and abort codes (§7.2.4.3.17, Table 22).
#pragma once
#include <linux/can.h>

#include <cstdint>

namespace rays::canopen {

struct SdoRequest {
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
    std::uint8_t size = 4;  // bytes, 1..4
    std::uint32_t value = 0;
    bool upload = false;  // a read; `size` and `value` unused
};

can_frame sdo_request_frame(int node, const SdoRequest& request);

enum class SdoReplyKind { Downloaded, Uploaded, Aborted, Other };

struct SdoReply {
    SdoReplyKind kind = SdoReplyKind::Other;
    std::uint16_t index = 0;
    std::uint8_t sub = 0;
    std::uint32_t value = 0;  // Uploaded: the value; Aborted: the abort code
    std::uint8_t size = 0;    // Uploaded: bytes
};

SdoReply parse_sdo_reply(const can_frame& frame);  // a frame from sdo_tx_id(node)
const char* sdo_abort_text(std::uint32_t code);

// Server side (the simulated drive).
can_frame sdo_download_ack(int node, std::uint16_t index, std::uint8_t sub);
can_frame sdo_upload_reply(int node, std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size);
can_frame sdo_abort(int node, std::uint16_t index, std::uint8_t sub, std::uint32_t code);

namespace sdo_abort_code {
constexpr std::uint32_t kTimeout = 0x05040000, kBadCommand = 0x05040001, kReadOnly = 0x06010002;
constexpr std::uint32_t kNoObject = 0x06020000, kLengthMismatch = 0x06070010, kNoSubIndex = 0x06090011;
constexpr std::uint32_t kValueRange = 0x06090030, kGeneral = 0x08000000, kDeviceState = 0x08000022;
}  // namespace sdo_abort_code

}  // namespace rays::canopen
