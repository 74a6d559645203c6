// SPDX-License-Identifier: Apache-2.0
// SocketCanTransport (skipped where the kernel has no CAN support) and the in-memory LoopbackBus.
#include <catch2/catch.hpp>
#include <cerrno>
#include <linux/can/error.h>
#include <sys/socket.h>
#include <unistd.h>

#include "drivers/can/can_frame_codec.hpp"
#include "drivers/can/sim/loopback_bus.hpp"
#include "drivers/can/socket_can_transport.hpp"
#include "support/skip.hpp"

using namespace rays;
using namespace rays::can;

namespace {

void skip_without_af_can() {
    const int probe = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (probe < 0 && errno == EAFNOSUPPORT)
        rays::test::skip("this kernel has no CAN support: socket(PF_CAN, SOCK_RAW, CAN_RAW) fails with EAFNOSUPPORT");
    if (probe >= 0) ::close(probe);
}

}  // namespace

TEST_CASE("SocketCanTransport reports a missing interface by name", "[can][socketcan]") {
    skip_without_af_can();
    SocketCanTransport transport("rays-nocan9");
    std::string error;
    CHECK_FALSE(transport.open(error));
    CHECK(error.find("rays-nocan9: no such interface") != std::string::npos);
}

TEST_CASE("SocketCanTransport sends and receives on vcan0", "[can][socketcan]") {
    skip_without_af_can();
    SocketCanTransport a("vcan0"), b("vcan0");
    std::string error;
    if (!a.open(error)) rays::test::skip("no vcan0 interface here (ip link add vcan0 type vcan): " + error);
    REQUIRE(b.open(error));
    can_frame frame = make_frame(0x123, 2);
    frame.data[0] = 0xAB;
    REQUIRE(a.send(frame) == CanIo::Ok);
    can_frame got{};
    REQUIRE(b.receive(got, std::chrono::seconds(10)) == CanIo::Ok);
    CHECK(got.can_id == 0x123u);
    CHECK(got.data[0] == 0xAB);
    b.wake();
    CHECK(b.receive(got, std::chrono::milliseconds(200)) == CanIo::Woken);
}

TEST_CASE("SocketCanTransport without CAN support fails to open with the reason", "[can][socketcan]") {
    const int probe = ::socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (probe >= 0) {
        ::close(probe);
        rays::test::skip("this kernel has CAN support; the failure path is for kernels without it");
    }
    SocketCanTransport transport("can0");
    std::string error;
    CHECK_FALSE(transport.open(error));
    CHECK(error.find("can0: socket(PF_CAN, SOCK_RAW, CAN_RAW): Address family not supported") != std::string::npos);
    can_frame frame = make_frame(0x1, 0);
    CHECK(transport.send(frame) == CanIo::Down);
}

TEST_CASE("LoopbackBus delivers to every other endpoint and records what was sent", "[can][loopback]") {
    SteadyClock clock;
    LoopbackBus bus(clock);
    LoopbackEndpoint& a = bus.add_endpoint();
    LoopbackEndpoint& b = bus.add_endpoint();
    LoopbackEndpoint& c = bus.add_endpoint();
    can_frame frame = make_frame(0x181, 4);
    put_u32(frame, 0, 0xDEADBEEF);
    REQUIRE(a.send(frame) == CanIo::Ok);
    can_frame got{};
    REQUIRE(b.receive(got, std::chrono::milliseconds(10)) == CanIo::Ok);
    CHECK(get_u32(got, 0) == 0xDEADBEEFu);
    REQUIRE(c.receive(got, std::chrono::milliseconds(10)) == CanIo::Ok);
    CHECK(a.receive(got, std::chrono::milliseconds(1)) == CanIo::Timeout);  // not back to the sender
    const auto records = bus.records();
    REQUIRE(records.size() == 1);
    CHECK(records[0].sender == 0);
    CHECK(records[0].frame.can_id == 0x181u);
    a.wake();
    CHECK(a.receive(got, std::chrono::milliseconds(100)) == CanIo::Woken);
}

TEST_CASE("LoopbackBus: ENOBUFS retries, muting and bus-off", "[can][loopback]") {
    SteadyClock clock;
    LoopbackBus bus(clock);
    LoopbackEndpoint& a = bus.add_endpoint();
    LoopbackEndpoint& b = bus.add_endpoint();
    can_frame frame = make_frame(0x201, 1);
    can_frame got{};
    a.fail_sends_with_enobufs(2);
    CHECK(a.send(frame) == CanIo::Ok);
    CHECK(a.counters().enobufs_retries == 2);
    a.fail_sends_with_enobufs(LoopbackEndpoint::kSendRetries + 1);
    CHECK(a.send(frame) == CanIo::Busy);
    CHECK(a.counters().dropped == 1);
    a.mute(true);
    CHECK(a.send(frame) == CanIo::Ok);
    a.mute(false);
    REQUIRE(b.receive(got, std::chrono::milliseconds(10)) == CanIo::Ok);  // only the first arrived
    CHECK(b.receive(got, std::chrono::milliseconds(1)) == CanIo::Timeout);
    bus.set_bus_off(true);
    REQUIRE(b.receive(got, std::chrono::milliseconds(10)) == CanIo::Ok);
    CHECK(classify_error_frame(got) == CanBusEvent::BusOff);
    CHECK(a.send(frame) == CanIo::Busy);
    bus.set_bus_off(false);
    REQUIRE(b.receive(got, std::chrono::milliseconds(10)) == CanIo::Ok);
    CHECK(classify_error_frame(got) == CanBusEvent::Restarted);
}
