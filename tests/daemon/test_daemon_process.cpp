// SPDX-License-Identifier: Apache-2.0
// The real raysd binary on a replayed sequence with the mock PTU, talked to over its socket as a
// user would: every command, bad input, many clients, a client that never reads, reloads, signals,
// sd_notify and socket activation.
#include <catch2/catch.hpp>

#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <fstream>
#include <sstream>

#include "common/frame_kernel.hpp"
#include "daemon_process.hpp"
#include "support/emulator.hpp"
#include "support/eventually.hpp"
#include "support/skip.hpp"

namespace {

using namespace rays::test;
using nlohmann::json;
namespace fs = std::filesystem;
using namespace std::chrono_literals;

struct Setup {
    fs::path dir;
    fs::path config;
    fs::path socket;
    fs::path log;
    fs::path records;
};

// A config replaying a generated sequence into the mock PTU; `extra` is appended to the file.
Setup make_setup(const std::string& name, const std::string& extra = "", bool paced = true) {
    Setup s;
    s.dir = fresh_dir(name);
    s.config = s.dir / "raysd.ini";
    s.socket = s.dir / "raysd.sock";
    s.log = s.dir / "raysd.log";
    s.records = s.dir / "ptu.csv";
    write_test_sequence(s.dir / "seq.y4m", 100);
    std::ofstream(s.config) << "[camera]\nsource = replay\nreplay_path = " << (s.dir / "seq.y4m").string()
                            << "\nreplay_loop = true\nreplay_paced = " << (paced ? "true" : "false") << "\n\n[mock]\nrecord_path = " << s.records.string()
                            << "\n\n[socket]\npath = " << s.socket.string() << "\n"
                            << extra;
    return s;
}

std::string read_file(const fs::path& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

// Runs raysctl and returns its exit status; its stdout goes to `out`.
int raysctl(const Setup& s, const std::string& args, std::string* out = nullptr) {
    fs::path captured = s.dir / "raysctl.out";
    std::string command = emulated(raysctl_binary().string()) + " --socket " + s.socket.string() + " " + args + " > " +
                          captured.string() + " 2>&1";
    int status = std::system(command.c_str());
    if (out != nullptr) *out = read_file(captured);
    return WEXITSTATUS(status);
}

// The last line of the mock's command record.
std::string last_record(const Setup& s) {
    std::istringstream lines(read_file(s.records));
    std::string line, last;
    while (std::getline(lines, line))
        if (!line.empty()) last = line;
    return last;
}

// A NOTIFY_SOCKET listener, as systemd would be.
class NotifyListener {
public:
    explicit NotifyListener(const fs::path& path) : path_(path) {
        fd_ = socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        std::strncpy(address.sun_path, path.c_str(), sizeof address.sun_path - 1);
        fs::remove(path);
        bind(fd_, reinterpret_cast<const sockaddr*>(&address), sizeof address);
        timeval wait{0, 100'000};
        setsockopt(fd_, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    }
    ~NotifyListener() { close(fd_); }
    // Collects messages until one contains `text`, or `timeout`.
    bool wait_for(const std::string& text, std::chrono::milliseconds timeout) {
        auto give_up = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < give_up) {
            char buffer[4096];
            ssize_t got = recv(fd_, buffer, sizeof buffer, 0);
            if (got > 0) received_ += std::string(buffer, static_cast<std::size_t>(got)) + "\n";
            if (received_.find(text) != std::string::npos) return true;
        }
        return false;
    }
    const std::string& received() const { return received_; }

private:
    fs::path path_;
    int fd_ = -1;
    std::string received_;
};

DaemonProcess start(const Setup& s, std::map<std::string, std::string> env = {}) {
    return DaemonProcess({raysd_binary().string(), "--config", s.config.string()}, env, s.log);
}

}  // namespace

TEST_CASE("config errors name file and line and exit with 78, --check-config validates") {
    Setup s = make_setup("config-errors");
    CHECK(std::system((emulated(raysd_binary().string()) + " --check-config " + s.config.string() + " > /dev/null").c_str()) == 0);
    fs::path bad = s.dir / "bad.ini";
    std::ofstream(bad) << "[rays]\nalpha = 0.1\nalpah = 0.2\n";
    DaemonProcess check({raysd_binary().string(), "--check-config", bad.string()}, {}, s.dir / "check.log");
    CHECK(check.wait(5s) == 78);
    CHECK(check.log().find(bad.string() + ":3: unknown parameter rays.alpah (did you mean rays.alpha?)") !=
          std::string::npos);
    std::ofstream(bad) << "[ptu]\ndriver = mock\n\n[camera]\nsource = webcam\n";
    DaemonProcess run({raysd_binary().string(), "--config", bad.string()}, {}, s.dir / "run.log");
    CHECK(run.wait(5s) == 78);
    CHECK(run.log().find(":5: camera.source = webcam is not one of sim|v4l2|replay") != std::string::npos);
    std::ofstream(bad) << "[loop]\nbudget_ms = 0\n";
    DaemonProcess range({raysd_binary().string(), "--check-config", bad.string()}, {}, s.dir / "range.log");
    CHECK(range.wait(5s) == 78);
    CHECK(range.log().find(":2: loop.budget_ms = 0 is out of range") != std::string::npos);
    std::ofstream(bad) << "[ptu]\ndriver = modbus\n\n[modbus]\npreset = custom\n";  // valid keys, no register map
    DaemonProcess driver({raysd_binary().string(), "--check-config", bad.string()}, {}, s.dir / "driver.log");
    CHECK(driver.wait(5s) == 78);
    CHECK(driver.log().find("[modbus] does not work for ptu.driver = modbus: ") != std::string::npos);
    // Run with it, raysd exits as for any bad file: 78, which raysd.service does not restart.
    DaemonProcess run_driver({raysd_binary().string(), "--config", bad.string()}, {}, s.dir / "run-driver.log");
    CHECK(run_driver.wait(5s) == 78);
    CHECK(run_driver.log().find("ptu.driver modbus: ") != std::string::npos);
}

TEST_CASE("raysd tells systemd READY=1 once serving, feeds the watchdog, and stops cleanly on SIGTERM") {
    Setup s = make_setup("notify", "[ptu]\npark_on_exit = true\npark_pan_deg = 0\npark_tilt_deg = -20\n");
    NotifyListener notify(s.dir / "notify.sock");
    DaemonProcess daemon = start(s, {{"NOTIFY_SOCKET", (s.dir / "notify.sock").string()},
                                     {"WATCHDOG_USEC", "400000"},
                                     {"WATCHDOG_PID", "$PID"}});
    REQUIRE(notify.wait_for("READY=1", 10s));
    CHECK(wait_for_socket(s.socket, 1s));  // bound before READY
    CHECK(notify.received().find("STATUS=tracking: replay") != std::string::npos);
    REQUIRE(notify.wait_for("WATCHDOG=1", 10s));
    CHECK(notify.wait_for("STATUS=tracking, automatic control, camera connected, PTU mock ok", 10s));
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
    CHECK(notify.wait_for("STOPPING=1", 1s));
    CHECK_FALSE(fs::exists(s.socket));
    // Parked first (a position command to tilt -20 deg), then both axes at zero velocity.
    std::string records = read_file(s.records);
    CHECK(records.find(",position,0,position,-0.34906585") != std::string::npos);
    CHECK(last_record(s).find(",velocity,0,velocity,0") != std::string::npos);
    CHECK(daemon.log().find("<5>stopped") != std::string::npos);
}

TEST_CASE("every command works over the socket, and raysctl's exit codes tell the outcome") {
    Setup s = make_setup("commands");
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));
    LineConnection c(s.socket);
    json banner = *c.read_json();
    CHECK(banner["class"] == "version");
    CHECK(banner["protocol"]["major"] == 1);

    REQUIRE(daemon.wait_for_log("tracking: replay", 5s));
    // The ready line says which build of the frame kernels runs here (the times depend on it).
    CHECK(daemon.wait_for_log(std::string(", frame kernels ") + rays::frame_kernel_build(), 1s));
    json status;
    CHECK(eventually([&] {  // a few frames through the loop
        status = c.request({{"cmd", "status"}});
        return status["frame"].get<long>() > 5;
    }));
    CHECK(status["class"] == "status");
    CHECK(status["camera"]["connected"] == true);
    CHECK(status["ptu"]["driver"] == "mock");
    CHECK(status["realtime"]["priority"] == "not requested");
    json stats = c.request({{"cmd", "stats"}});
    CHECK(stats["frames"].get<long>() > 5);
    CHECK(stats["loop_us"]["p99"].get<double>() > 0);

    CHECK(c.request({{"cmd", "set"}, {"name", "rays.alpha"}, {"value", 0.05}})["value"] == Approx(0.05));
    CHECK(c.request({{"cmd", "get"}, {"name", "rays.alpha"}})["value"] == Approx(0.05));
    CHECK(c.request({{"cmd", "track"}, {"x", 64}, {"y", 64}})["class"] == "ok");
    CHECK(c.request({{"cmd", "release"}})["class"] == "ok");
    CHECK(c.request({{"cmd", "reinit"}})["class"] == "ok");

    CHECK(c.request({{"cmd", "ptu"}, {"action", "goto"}, {"pan_deg", 10}, {"tilt_deg", 5}})["class"] == "ok");
    CHECK(eventually([&] {  // the unit moves there
        status = c.request({{"cmd", "status"}});
        return std::abs(status["ptu"]["pan_deg"].get<double>() - 10) < 0.1 &&
               std::abs(status["ptu"]["tilt_deg"].get<double>() - 5) < 0.1;
    }));
    CHECK(status["mode"] == "manual");
    CHECK(c.request({{"cmd", "ptu"}, {"action", "jog"}, {"pan_deg_s", 20}, {"tilt_deg_s", 0}})["class"] == "ok");
    auto pan_deg_s = [&] { return c.request({{"cmd", "status"}})["ptu"]["pan_deg_s"].get<double>(); };
    CHECK(eventually([&] { return pan_deg_s() > 5; }));
    CHECK(eventually([&] { return std::abs(pan_deg_s()) < 0.01; }));  // not renewed: the jog ends by itself
    CHECK(c.request({{"cmd", "ptu"}, {"action", "home"}})["class"] == "ok");
    CHECK(c.request({{"cmd", "ptu"}, {"action", "park"}})["class"] == "ok");
    CHECK(c.request({{"cmd", "ptu"}, {"action", "stop"}})["class"] == "ok");
    CHECK(c.request({{"cmd", "resume"}})["class"] == "ok");
    CHECK(eventually([&] { return c.request({{"cmd", "status"}})["mode"] == "automatic"; }));

    json snapshot = c.request({{"cmd", "snapshot"}});
    CHECK(snapshot["class"] == "snapshot");
    CHECK(snapshot["data"].get<std::string>().rfind("iVBORw0KGgo", 0) == 0);  // base64 of the PNG signature

    CHECK(c.request({{"cmd", "watch"}, {"enable", true}})["enable"] == true);
    int frames = 0;
    long last = -1;
    for (int i = 0; i < 200 && frames < 10; ++i) {
        std::optional<json> record = c.read_json(10s);
        REQUIRE(record);
        if ((*record)["class"] != "frame") continue;
        CHECK((*record)["frame"].get<long>() > last);
        CHECK((*record)["psr"].get<double>() >= 0.0);  // how surely the target's looks were found (0: not tracking)
        last = (*record)["frame"].get<long>();
        ++frames;
    }
    CHECK(frames == 10);
    CHECK(c.request({{"cmd", "watch"}, {"enable", false}})["enable"] == false);

    std::string out;
    CHECK(raysctl(s, "status", &out) == 0);
    CHECK(out.find("ptu        mock") != std::string::npos);
    CHECK(raysctl(s, "--json stats", &out) == 0);
    CHECK(json::parse(out)["class"] == "stats");
    CHECK(raysctl(s, "set rays.alpha -3", &out) == 1);
    CHECK(out.find("bad_param") != std::string::npos);
    CHECK(raysctl(s, "set rays.alpha 0.4", &out) == 0);
    CHECK(out == "rays.alpha = 0.40\n");
    CHECK(raysctl(s, "track 64 60") == 0);
    CHECK(raysctl(s, "track 64") == 2);
    CHECK(raysctl(s, "track 40 30 24 16") == 0);
    CHECK(raysctl(s, "track 40 30 24") == 2);
    CHECK(raysctl(s, "track 40 30 -24 16", &out) == 1);
    CHECK(out.find("width and height must be above 0") != std::string::npos);
    CHECK(raysctl(s, "snapshot " + (s.dir / "snap.png").string()) == 0);
    CHECK(read_file(s.dir / "snap.png").substr(1, 3) == "PNG");
    CHECK(raysctl(s, "watch 3", &out) == 0);
    CHECK(std::count(out.begin(), out.end(), '\n') == 3);
    CHECK(out.find(" psr ") != std::string::npos);
    CHECK(std::system((emulated(raysctl_binary().string()) + " --socket " + (s.dir / "none.sock").string() +
                       " status 2>/dev/null").c_str()) >> 8 == 3);
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}

TEST_CASE("malformed and oversized requests get errors and the connection stays usable") {
    Setup s = make_setup("malformed", "max_line_bytes = 256\n");
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));
    LineConnection c(s.socket);
    c.read_json();
    c.send_raw("{\"cmd\": \n");
    CHECK((*c.read_json())["error"]["code"] == "bad_json");
    c.send_raw("\x01\x02\xff\xfe garbage\n");
    CHECK((*c.read_json())["error"]["code"] == "bad_json");
    c.send_raw("{\"cmd\":\"" + std::string(5000, 'x') + "\"}\n");
    CHECK((*c.read_json())["error"]["code"] == "line_too_long");
    c.send_raw(std::string(300, ' '));  // an over-long line arriving in pieces
    c.send_raw(std::string(300, 'y') + "\n");
    CHECK((*c.read_json())["error"]["code"] == "line_too_long");
    c.send_raw("{\"cmd\":\"flyaway\"}\n");
    CHECK((*c.read_json())["error"]["code"] == "unknown_command");
    CHECK(c.request({{"cmd", "status"}})["class"] == "status");
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}

TEST_CASE("many clients are served up to the limit, a client that never reads is dropped, not waited for") {
    // Unpaced replay: as many frames as the loop takes, so a silent watcher's backlog grows fast.
    Setup s = make_setup("clients", "max_clients = 4\nmax_output_kib = 16\n", false);
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));

    LineConnection silent(s.socket);  // watches and never reads
    int small = 4096;
    setsockopt(silent.fd(), SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    silent.send_raw("{\"cmd\":\"watch\"}\n");
    std::vector<std::unique_ptr<LineConnection>> clients;
    for (int i = 0; i < 3; ++i) {
        clients.push_back(std::make_unique<LineConnection>(s.socket));
        CHECK((*clients.back()->read_json())["class"] == "version");
    }
    LineConnection extra(s.socket);
    json refused = *extra.read_json();
    CHECK(refused["error"]["code"] == "too_many_clients");

    REQUIRE(daemon.wait_for_log("dropped a client: it does not read its replies", 10s));
    long frames_before = clients[0]->request({{"cmd", "status"}})["frame"];
    CHECK(eventually([&] {  // the loop never waited
        return clients[0]->request({{"cmd", "status"}})["frame"].get<long>() > frames_before;
    }));
    LineConnection fresh(s.socket);  // the dropped client's place is free again
    CHECK((*fresh.read_json())["class"] == "version");
    for (auto& client : clients) CHECK(client->request({{"cmd", "version"}})["class"] == "version");
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}

TEST_CASE("a client that hung up before raysd read it holds no place: connections arriving together are all served") {
    Setup s = make_setup("hung-up", "max_clients = 2\n");
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));
    REQUIRE(eventually([&] { return LineConnection(s.socket).read_json(1s).has_value(); }));
    // raysd stopped: the three connections wait in the listen queue, the first already closed, and
    // reach the server in one accept loop (as on a loaded machine, where they arrive faster than it polls).
    daemon.signal(SIGSTOP);
    { LineConnection probe(s.socket); }
    LineConnection first(s.socket), second(s.socket);
    daemon.signal(SIGCONT);
    CHECK((*first.read_json(10s))["class"] == "version");
    CHECK((*second.read_json(10s))["class"] == "version");
    LineConnection third(s.socket);  // and the limit still holds
    CHECK((*third.read_json(10s))["error"]["code"] == "too_many_clients");
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}

TEST_CASE("SIGHUP reloads tunables without dropping the track, a bad reload is refused and changes nothing") {
    Setup s = make_setup("reload");
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));
    LineConnection c(s.socket);
    c.read_json();
    CHECK(c.request({{"cmd", "set"}, {"name", "rays.beta"}, {"value", 0.5}})["value"] == Approx(0.5));
    std::ofstream(s.config, std::ios::app) << "\n[rays]\nalpha = 0.07\nmax_rays = 360\n";
    daemon.signal(SIGHUP);
    REQUIRE(daemon.wait_for_log("reloaded tunables", 5s));
    CHECK(daemon.log().find("rays.max_rays changed, which takes a restart") != std::string::npos);
    CHECK(c.request({{"cmd", "get"}, {"name", "rays.alpha"}})["value"] == Approx(0.07));
    CHECK(c.request({{"cmd", "get"}, {"name", "rays.beta"}})["value"] == Approx(1e-6));  // the file's value again
    CHECK(c.request({{"cmd", "get"}, {"name", "rays.max_rays"}})["value"] == 720);

    std::ofstream(s.config, std::ios::app) << "hypotheses = 99\n";
    daemon.signal(SIGHUP);
    REQUIRE(daemon.wait_for_log("reload refused, running settings kept", 5s));
    CHECK(daemon.log().find("raysd.ini:16: rays.hypotheses = 99 is out of range") != std::string::npos);
    CHECK(c.request({{"cmd", "get"}, {"name", "rays.alpha"}})["value"] == Approx(0.07));
    CHECK(c.request({{"cmd", "status"}})["class"] == "status");
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}

TEST_CASE("under systemd socket activation raysd serves the passed socket and never removes it") {
    if (system("command -v systemd-socket-activate > /dev/null") != 0)
        rays::test::skip("systemd-socket-activate is not installed (Debian package systemd)");
    Setup s = make_setup("activation");
    fs::path other = s.dir / "activated.sock";
    DaemonProcess daemon({"/usr/bin/systemd-socket-activate", "-l", other.string(), raysd_binary().string(),
                          "--config", s.config.string()},
                         {}, s.log);
    REQUIRE(wait_for_socket(other, 5s));
    LineConnection c(other);  // the first connection starts raysd
    std::optional<json> banner = c.read_json(10s);
    REQUIRE(banner);
    CHECK((*banner)["class"] == "version");
    CHECK(c.request({{"cmd", "status"}})["class"] == "status");
    CHECK(daemon.wait_for_log("socket from systemd", 5s));
    CHECK_FALSE(fs::exists(s.socket));  // its own path unused
    daemon.signal(SIGTERM);
    daemon.wait(5s);
    CHECK(fs::exists(other));
}

TEST_CASE("real-time options are applied or their refusal is reported in the log and the status") {
    Setup s = make_setup("realtime", "[loop]\nrt_priority = 10\ncpu = 0\nlock_memory = true\n");
    DaemonProcess daemon = start(s);
    REQUIRE(wait_for_socket(s.socket, 10s));
    LineConnection c(s.socket);
    c.read_json();
    json realtime = c.request({{"cmd", "status"}})["realtime"];
    std::string priority = realtime["priority"], affinity = realtime["affinity"], memory = realtime["memory_lock"];
    INFO(priority << " / " << affinity << " / " << memory);
    CHECK((priority == "SCHED_FIFO 10" || priority.rfind("refused: SCHED_FIFO 10: ", 0) == 0));
    CHECK((affinity == "pinned to CPU 0" || affinity.rfind("refused: CPU 0: ", 0) == 0));
    CHECK((memory == "locked (mlockall)" || memory.rfind("refused: mlockall: ", 0) == 0));
    for (const std::string& report : {priority, affinity, memory})
        if (report.rfind("refused", 0) == 0) CHECK(daemon.log().find(report) != std::string::npos);
    daemon.signal(SIGTERM);
    CHECK(daemon.wait(10s) == 0);
}
