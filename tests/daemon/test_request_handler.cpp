// SPDX-License-Identifier: Apache-2.0
// The command socket's request handling, in-process: every command's reply, every error class, and
// what actually reaches the frame loop's command queue.
#include <catch2/catch.hpp>

#include "core/clock.hpp"
#include "daemon/daemon_params.hpp"
#include "daemon/request_handler.hpp"

namespace {

using namespace rays::daemon;
using nlohmann::json;

struct Fixture {
    rays::SteadyClock clock;
    DaemonConfig config;
    LoopChannels channels{2};
    RequestHandler handler{config, channels, DaemonFacts{"mock"}, [] { return std::string("camera ok"); }, clock};
    ClientSession session;

    json ask(const std::string& line) { return handler.handle(line, session); }
    std::string error_code(const std::string& line) {
        json reply = ask(line);
        REQUIRE(reply["class"] == "error");
        return reply["error"]["code"];
    }
    LoopCommand take() {
        LoopCommand command;
        REQUIRE(channels.commands.pop(command));
        return command;
    }
};

}  // namespace

TEST_CASE("malformed requests get a JSON error naming the problem") {
    Fixture f;
    CHECK(f.error_code("{not json") == "bad_json");
    CHECK(f.error_code("[1,2]") == "bad_request");
    CHECK(f.error_code(R"({"command":"status"})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":42})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"statsu"})") == "unknown_command");
    CHECK(f.error_code(R"({"cmd":"track","x":"a","y":3})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"track","x":200,"y":3})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"ptu"})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"ptu","action":"dance"})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"ptu","action":"jog","pan_deg_s":1})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"watch","enable":"yes"})") == "bad_request");
    CHECK(f.error_code(R"({"cmd":"snapshot"})") == "not_available");
    CHECK(f.channels.commands.empty());
}

TEST_CASE("a request's id comes back with its reply, errors included") {
    Fixture f;
    CHECK(f.ask(R"({"cmd":"status","id":7})")["id"] == 7);
    CHECK(f.ask(R"({"cmd":"nope","id":"abc"})")["id"] == "abc");
}

TEST_CASE("get and set are validated as the config file is, and set reaches the frame loop") {
    Fixture f;
    json one = f.ask(R"({"cmd":"get","name":"rays.alpha"})");
    CHECK(one["class"] == "param");
    CHECK(one["value"] == Approx(0.02));
    CHECK(one["kind"] == "tunable");
    json all = f.ask(R"({"cmd":"get"})");
    CHECK(all["class"] == "params");
    CHECK(all["values"]["socket.path"] == "/run/raysd/raysd.sock");

    json set = f.ask(R"({"cmd":"set","name":"rays.alpha","value":0.4})");
    CHECK(set["class"] == "param");
    CHECK(set["value"] == Approx(0.4));
    LoopCommand sent = f.take();
    CHECK(sent.kind == CommandKind::Tunables);
    CHECK(sent.tunables.tracker.rays.alpha == Approx(0.4));
    CHECK(f.config.tracker.tunables.rays.alpha == Approx(0.4));

    CHECK(f.ask(R"({"cmd":"set","name":"loop.budget_ms","value":"5"})")["value"] == Approx(5.0));
    CHECK(f.take().tunables.budget_ms == Approx(5.0));

    json out_of_range = f.ask(R"({"cmd":"set","name":"rays.alpha","value":-1})");
    CHECK(out_of_range["error"]["code"] == "bad_param");
    CHECK(out_of_range["error"]["message"].get<std::string>().find("out of range") != std::string::npos);
    CHECK(f.error_code(R"({"cmd":"set","name":"rays.max_rays","value":100})") == "bad_param");
    CHECK(f.error_code(R"({"cmd":"set","name":"rays.alpah","value":1})") == "bad_param");
    CHECK(f.error_code(R"({"cmd":"set","name":"rays.count","value":9999})") == "bad_param");  // > max_rays
    CHECK(f.error_code(R"({"cmd":"get","name":"nope.key"})") == "bad_param");
    CHECK(f.channels.commands.empty());
    CHECK(f.config.tracker.tunables.rays.alpha == Approx(0.4));
}

TEST_CASE("track, release, reinit, resume and every ptu action queue their command") {
    Fixture f;
    CHECK(f.ask(R"({"cmd":"track","x":64,"y":60.5})")["class"] == "ok");
    LoopCommand track = f.take();
    CHECK(track.kind == CommandKind::Track);
    CHECK(track.a == 64);
    CHECK(track.b == 60.5);
    for (auto [line, kind] : {std::pair{R"({"cmd":"release"})", CommandKind::Release},
                              std::pair{R"({"cmd":"reinit"})", CommandKind::Reinit},
                              std::pair{R"({"cmd":"resume"})", CommandKind::Resume},
                              std::pair{R"({"cmd":"ptu","action":"stop"})", CommandKind::Stop},
                              std::pair{R"({"cmd":"ptu","action":"home"})", CommandKind::Home},
                              std::pair{R"({"cmd":"ptu","action":"park"})", CommandKind::Park}}) {
        CHECK(f.ask(line)["class"] == "ok");
        CHECK(f.take().kind == kind);
    }
    CHECK(f.ask(R"({"cmd":"ptu","action":"jog","pan_deg_s":90,"tilt_deg_s":-45})")["class"] == "ok");
    LoopCommand jog = f.take();
    CHECK(jog.kind == CommandKind::Jog);
    CHECK(jog.a == Approx(M_PI / 2));
    CHECK(jog.b == Approx(-M_PI / 4));
    CHECK(f.ask(R"({"cmd":"ptu","action":"goto","pan_deg":180,"tilt_deg":0})")["class"] == "ok");
    CHECK(f.take().a == Approx(M_PI));
}

TEST_CASE("track with w and h queues a box start, a malformed box gets a JSON error saying why") {
    Fixture f;
    CHECK(f.ask(R"({"cmd":"track","x":40,"y":30.5,"w":24,"h":16})")["class"] == "ok");
    LoopCommand box = f.take();
    CHECK(box.kind == CommandKind::TrackBox);
    CHECK(box.box.x == 40);
    CHECK(box.box.y == 30.5);
    CHECK(box.box.w == 24);
    CHECK(box.box.h == 16);
    CHECK(f.ask(R"({"cmd":"track","x":0,"y":0,"w":128,"h":128})")["class"] == "ok");  // the whole frame
    CHECK(f.take().kind == CommandKind::TrackBox);

    auto message = [&](const std::string& line) {
        json reply = f.ask(line);
        REQUIRE(reply["class"] == "error");
        CHECK(reply["error"]["code"] == "bad_request");
        return reply["error"]["message"].get<std::string>();
    };
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"w":24})") == "track: a box needs both \"w\" and \"h\"");
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"h":16})") == "track: a box needs both \"w\" and \"h\"");
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"w":"24","h":16})") == "track needs a number \"w\"");
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"w":24,"h":null})") == "track needs a number \"h\"");
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"w":0,"h":16})") ==
          "track: the box's width and height must be above 0");
    CHECK(message(R"({"cmd":"track","x":40,"y":30,"w":24,"h":-16})").find("above 0") != std::string::npos);
    CHECK(message(R"({"cmd":"track","x":120,"y":30,"w":24,"h":16})") ==
          "track: the box must lie inside the 128x128 processing frame: x and y at least 0, x + w and y + h at most 128");
    CHECK(message(R"({"cmd":"track","x":-2,"y":30,"w":24,"h":16})").find("inside") != std::string::npos);
    CHECK(message(R"({"cmd":"track","y":30,"w":24,"h":16})") == "track needs a number \"x\"");
    CHECK(f.channels.commands.empty());
}

TEST_CASE("a full command queue answers busy and loses nothing already queued") {
    Fixture f;
    int accepted = 0;
    for (int i = 0; i < 100; ++i)
        if (f.ask(R"({"cmd":"release"})")["class"] == "ok") ++accepted;
    CHECK(accepted == 64);
    CHECK(f.error_code(R"({"cmd":"release"})") == "busy");
    int taken = 0;
    LoopCommand command;
    while (f.channels.commands.pop(command)) ++taken;
    CHECK(taken == accepted);
}

TEST_CASE("watch switches the client's telemetry on and off, status and stats report") {
    Fixture f;
    CHECK(f.ask(R"({"cmd":"watch"})")["enable"] == true);
    CHECK(f.session.watching);
    CHECK(f.ask(R"({"cmd":"watch","enable":false})")["enable"] == false);
    CHECK_FALSE(f.session.watching);
    json status = f.ask(R"({"cmd":"status"})");
    CHECK(status["class"] == "status");
    CHECK(status["ptu"]["driver"] == "mock");
    CHECK(status["camera"]["status"] == "camera ok");
    json stats = f.ask(R"({"cmd":"stats"})");
    CHECK(stats["class"] == "stats");
    CHECK(stats["frames"] == 0);
    CHECK(stats["loop_histogram"].size() == kHistogramBins);
    json version = f.ask(R"({"cmd":"version"})");
    CHECK(version["protocol"]["major"] == kProtocolMajor);
}

TEST_CASE("a request nested deeper than 64 levels is refused, not copied into its reply") {
    Fixture f;
    auto with_id_depth = [](int levels) {
        return R"({"cmd":"status","id":)" + std::string(static_cast<std::size_t>(levels), '[') +
               std::string(static_cast<std::size_t>(levels), ']') + "}";
    };
    CHECK(f.ask(with_id_depth(63))["class"] == "status");
    CHECK(f.error_code(with_id_depth(64)) == "bad_request");
    json deep = f.ask(with_id_depth(200000));  // overflowed the stack when the id was copied
    CHECK(deep["error"]["code"] == "bad_request");
    CHECK(!deep.contains("id"));
    CHECK(f.error_code(std::string(100000, '[')) == "bad_json");
}

