// SPDX-License-Identifier: Apache-2.0
// raysctl: the command-line client of raysd's command socket (docs/protocol.md).
// Exit status: 0 done; 1 raysd answered with an error; 2 bad usage; 3 cannot connect;
// 4 no or unreadable reply; 5 a local file could not be written.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "daemon/base64.hpp"
#include "reply_printer.hpp"
#include "socket_client.hpp"

namespace {

using nlohmann::json;
using rays::ctl::SocketClient;

enum Exit { kOk = 0, kServerError = 1, kUsage = 2, kNoConnection = 3, kNoReply = 4, kLocalFile = 5 };

void usage(std::FILE* out) {
    std::fputs(
        "usage: raysctl [--socket PATH] [--json] [--timeout SECONDS] COMMAND [ARGS]\n"
        "commands:\n"
        "  status | stats | version\n"
        "  get [NAME]                   one parameter, or all of them\n"
        "  set NAME VALUE               change a tunable until the next reload\n"
        "  track X Y [W H]              start tracking at processing pixel (X, Y), or in the box\n"
        "                               with top-left corner (X, Y), width W and height H\n"
        "  release | reinit | resume\n"
        "  ptu jog PAN_DEG_S TILT_DEG_S | ptu goto PAN_DEG TILT_DEG | ptu stop | ptu home | ptu park\n"
        "  snapshot FILE.png            the newest frame with the contour drawn\n"
        "  watch [COUNT]                per-frame telemetry (COUNT frames, or until interrupted)\n"
        "The socket defaults to $RAYSD_SOCKET, else /run/raysd/raysd.sock.\n",
        out);
}

bool parse_number(const std::string& text, double& out) {
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return !text.empty() && end == text.c_str() + text.size();
}

// The request for COMMAND ARGS, or nullopt for bad usage.
std::optional<json> build_request(const std::vector<std::string>& args) {
    const std::string& cmd = args[0];
    std::size_t n = args.size();
    double a = 0, b = 0, w = 0, h = 0;
    if ((cmd == "status" || cmd == "stats" || cmd == "version" || cmd == "release" || cmd == "reinit" ||
         cmd == "resume" || cmd == "snapshot") && n == (cmd == "snapshot" ? 2u : 1u))
        return json{{"cmd", cmd}};
    if (cmd == "get" && n <= 2) return n == 1 ? json{{"cmd", "get"}} : json{{"cmd", "get"}, {"name", args[1]}};
    if (cmd == "set" && n == 3) return json{{"cmd", "set"}, {"name", args[1]}, {"value", args[2]}};
    if (cmd == "track" && n == 3 && parse_number(args[1], a) && parse_number(args[2], b))
        return json{{"cmd", "track"}, {"x", a}, {"y", b}};
    if (cmd == "track" && n == 5 && parse_number(args[1], a) && parse_number(args[2], b) && parse_number(args[3], w) &&
        parse_number(args[4], h))
        return json{{"cmd", "track"}, {"x", a}, {"y", b}, {"w", w}, {"h", h}};
    if (cmd == "watch" && n <= 2) return json{{"cmd", "watch"}, {"enable", true}};
    if (cmd == "ptu" && n == 2 && (args[1] == "stop" || args[1] == "home" || args[1] == "park"))
        return json{{"cmd", "ptu"}, {"action", args[1]}};
    if (cmd == "ptu" && n == 4 && parse_number(args[2], a) && parse_number(args[3], b)) {
        if (args[1] == "jog") return json{{"cmd", "ptu"}, {"action", "jog"}, {"pan_deg_s", a}, {"tilt_deg_s", b}};
        if (args[1] == "goto") return json{{"cmd", "ptu"}, {"action", "goto"}, {"pan_deg", a}, {"tilt_deg", b}};
    }
    return std::nullopt;
}

int write_snapshot(const json& reply, const std::string& path) {
    std::vector<std::uint8_t> png;
    if (!reply.contains("data") || !reply["data"].is_string() ||
        !rays::daemon::base64_decode(reply["data"].get<std::string>(), png)) {
        std::fprintf(stderr, "raysctl: the snapshot reply holds no valid image data\n");
        return kNoReply;
    }
    std::ofstream file(path, std::ios::binary);
    file.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    if (!file.flush()) {
        std::fprintf(stderr, "raysctl: cannot write %s\n", path.c_str());
        return kLocalFile;
    }
    return kOk;
}

int watch(SocketClient& client, long count, bool as_json, std::chrono::milliseconds timeout) {
    std::string error;
    for (long seen = 0; count <= 0 || seen < count;) {
        std::optional<json> record = client.receive(timeout, error);
        if (!record) {
            std::fprintf(stderr, "raysctl: %s\n", error.c_str());
            return kNoReply;
        }
        if (record->value("class", "") != "frame") continue;
        rays::ctl::print_reply(*record, as_json);
        std::fflush(stdout);
        ++seen;
    }
    return kOk;
}

}  // namespace

int main(int argc, char** argv) {
    const char* env_socket = std::getenv("RAYSD_SOCKET");
    std::string socket_path = env_socket != nullptr ? env_socket : "/run/raysd/raysd.sock";
    bool as_json = false;
    double timeout_s = 5.0;
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--socket" && i + 1 < argc) socket_path = argv[++i];
        else if (arg == "--json") as_json = true;
        else if (arg == "--timeout" && i + 1 < argc && parse_number(argv[i + 1], timeout_s) && timeout_s > 0) ++i;
        else if (arg == "--help" || arg == "-h") {
            usage(stdout);
            return kOk;
        } else if (!arg.empty() && arg[0] == '-' && args.empty()) {
            std::fprintf(stderr, "raysctl: unknown or incomplete option '%s'\n", arg.c_str());
            usage(stderr);
            return kUsage;
        } else args.push_back(arg);
    }
    if (args.empty()) {
        usage(stderr);
        return kUsage;
    }
    std::optional<json> request = build_request(args);
    if (!request) {
        std::fprintf(stderr, "raysctl: bad arguments for '%s'\n", args[0].c_str());
        usage(stderr);
        return kUsage;
    }
    auto timeout = std::chrono::milliseconds(static_cast<long>(timeout_s * 1000));
    std::string error;
    std::optional<SocketClient> client = SocketClient::connect(socket_path, timeout, error);
    if (!client) {
        std::fprintf(stderr, "raysctl: %s\n", error.c_str());
        return kNoConnection;
    }
    if (args[0] == "version") {
        rays::ctl::print_reply(client->banner(), as_json);
        return kOk;
    }
    if (!client->send(*request, error)) {
        std::fprintf(stderr, "raysctl: %s\n", error.c_str());
        return kNoReply;
    }
    std::optional<json> reply = client->receive(timeout, error);
    if (!reply) {
        std::fprintf(stderr, "raysctl: %s\n", error.c_str());
        return kNoReply;
    }
    if (reply->value("class", "") == "error") {
        rays::ctl::print_reply(*reply, as_json);
        return kServerError;
    }
    if (args[0] == "snapshot") {
        int status = write_snapshot(*reply, args[1]);
        if (status == kOk && !as_json) std::printf("frame %ld written to %s\n", reply->value("frame", -1L), args[1].c_str());
        if (status == kOk && as_json) std::printf("%s\n", json{{"class", "snapshot"}, {"frame", (*reply)["frame"]}, {"file", args[1]}}.dump().c_str());
        return status;
    }
    if (args[0] == "watch") return watch(*client, args.size() > 1 ? std::atol(args[1].c_str()) : 0, as_json, timeout);
    rays::ctl::print_reply(*reply, as_json);
    return kOk;
}
