// SPDX-License-Identifier: Apache-2.0
// The real raysd binary with driver = canopen against `ptu-sim --can`, two simulated CiA 402 drives
// in another process, on a real SocketCAN interface. Runs where a vcan0 interface exists
// (`ip link add dev vcan0 type vcan && ip link set up vcan0`); skipped, saying why, elsewhere.
#include <catch2/catch.hpp>

#include <net/if.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <linux/can.h>

#include <thread>

#include "daemon_process.hpp"
#include "sim_process.hpp"
#include "support/skip.hpp"

using namespace rays::test;
using nlohmann::json;
using namespace std::chrono_literals;

TEST_CASE("raysd with driver = canopen moves ptu-sim's CiA 402 drives on vcan0") {
    int probe = socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (probe < 0) skip("this kernel has no CAN support: socket(PF_CAN, SOCK_RAW, CAN_RAW) fails");
    close(probe);
    if (if_nametoindex("vcan0") == 0) skip("no vcan0 interface (ip link add dev vcan0 type vcan; ip link set up vcan0)");

    std::filesystem::path dir = fresh_dir("can");
    std::filesystem::path ini = write_replay_config(dir, "[ptu]\ndriver = canopen\n\n[canopen]\ninterface = vcan0\n");
    SimProcess sim({RAYS_PTU_SIM, "--can", "vcan0", "--can-nodes", "1,2"});
    REQUIRE(sim.ready());
    DaemonProcess daemon({raysd_binary().string(), "--config", ini.string()}, {}, dir / "raysd.log");
    INFO(daemon.log());
    REQUIRE(wait_for_socket(dir / "raysd.sock", 10s));
    LineConnection c(dir / "raysd.sock");
    c.read_json();
    CHECK(c.request({{"cmd", "ptu"}, {"action", "goto"}, {"pan_deg", 10}, {"tilt_deg", -5}})["class"] == "ok");
    json status;
    for (int i = 0; i < 80; ++i) {
        status = c.request({{"cmd", "status"}});
        if (std::abs(status["ptu"]["pan_deg"].get<double>() - 10) < 0.2) break;
        std::this_thread::sleep_for(100ms);
    }
    CHECK(status["ptu"]["driver"] == "canopen");
    CHECK(status["ptu"]["pan_deg"].get<double>() == Approx(10).margin(0.2));
    CHECK(status["ptu"]["tilt_deg"].get<double>() == Approx(-5).margin(0.2));
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(5s) == 0);
}
