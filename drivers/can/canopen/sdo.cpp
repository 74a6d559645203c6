// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/canopen/sdo.hpp"

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/canopen/canopen_ids.hpp"

namespace rays::canopen {
namespace {

// Command specifier byte, CiA 301 §7.2.4.3.3-7: ccs/scs in bits 7-5, n (unused bytes) in 3-2,
// e (expedited) bit 1, s (size indicated) bit 0.
constexpr std::uint8_t kDownloadRequest = 0x20, kUploadRequest = 0x40, kDownloadAck = 0x60, kUploadReply = 0x40;
constexpr std::uint8_t kAbort = 0x80, kExpeditedSized = 0x03;

can_frame frame_for(std::uint32_t id, std::uint8_t command, std::uint16_t index, std::uint8_t sub) {
    can_frame frame = can::make_frame(id, 8);
    frame.data[0] = command;
    can::put_u16(frame, 1, index);
    frame.data[3] = sub;
    return frame;
}

}  // namespace

can_frame sdo_request_frame(int node, const SdoRequest& request) {
    if (request.upload) return frame_for(sdo_rx_id(node), kUploadRequest, request.index, request.sub);
    const auto unused = static_cast<std::uint8_t>((4 - request.size) << 2);
    can_frame frame = frame_for(sdo_rx_id(node), kDownloadRequest | unused | kExpeditedSized, request.index, request.sub);
    can::put_u32(frame, 4, request.value);
    return frame;
}

SdoReply parse_sdo_reply(const can_frame& frame) {
    SdoReply reply;
    if (frame.len < 8) return reply;
    reply.index = can::get_u16(frame, 1);
    reply.sub = frame.data[3];
    const std::uint8_t command = frame.data[0];
    if (command == kAbort) {
        reply.kind = SdoReplyKind::Aborted;
        reply.value = can::get_u32(frame, 4);
    } else if (command == kDownloadAck) {
        reply.kind = SdoReplyKind::Downloaded;
    } else if ((command & 0xE3) == (kUploadReply | kExpeditedSized)) {
        reply.kind = SdoReplyKind::Uploaded;
        reply.size = static_cast<std::uint8_t>(4 - ((command >> 2) & 0x3));
        const std::uint32_t raw = can::get_u32(frame, 4);
        reply.value = reply.size == 4 ? raw : raw & ((1u << (8 * reply.size)) - 1u);
    }
    return reply;
}

const char* sdo_abort_text(std::uint32_t code) {
    using namespace sdo_abort_code;
    switch (code) {
        case kTimeout: return "SDO protocol timed out";
        case kBadCommand: return "command specifier not valid";
        case kReadOnly: return "attempt to write a read only object";
        case kNoObject: return "object does not exist";
        case kLengthMismatch: return "length of service parameter does not match";
        case kNoSubIndex: return "sub-index does not exist";
        case kValueRange: return "value range of parameter exceeded";
        case kGeneral: return "general error";
        case kDeviceState: return "not possible in the present device state";
        default: return "abort";
    }
}

can_frame sdo_download_ack(int node, std::uint16_t index, std::uint8_t sub) {
    return frame_for(sdo_tx_id(node), kDownloadAck, index, sub);
}

can_frame sdo_upload_reply(int node, std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::uint8_t size) {
    const auto unused = static_cast<std::uint8_t>((4 - size) << 2);
    can_frame frame = frame_for(sdo_tx_id(node), kUploadReply | unused | kExpeditedSized, index, sub);
    can::put_u32(frame, 4, value);
    return frame;
}

can_frame sdo_abort(int node, std::uint16_t index, std::uint8_t sub, std::uint32_t code) {
    can_frame frame = frame_for(sdo_tx_id(node), kAbort, index, sub);
    can::put_u32(frame, 4, code);
    return frame;
}

}  // namespace rays::canopen
