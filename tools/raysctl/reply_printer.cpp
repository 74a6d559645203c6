// SPDX-License-Identifier: Apache-2.0
#include "reply_printer.hpp"

#include <cstdio>
#include <string>

namespace rays::ctl {
namespace {

using nlohmann::json;

std::string text(const json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_number_float()) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.2f", value.get<double>());
        return buffer;
    }
    if (value.is_array()) {
        std::string list = "(";
        for (const json& item : value) list += (list.size() > 1 ? ", " : "") + text(item);
        return list + ")";
    }
    return value.dump();
}

std::string field(const json& object, const char* key) {
    auto found = object.find(key);
    return found == object.end() ? "-" : text(*found);
}

void print_status(const json& s) {
    const json& ref = s["ref"];
    std::printf("state      %s (frame %s)%s\n", field(s, "state").c_str(), field(s, "frame").c_str(),
                ref.is_array() ? (", m at (" + text(ref[0]) + ", " + text(ref[1]) + "), area " + field(s, "area_px") +
                                  " px^2").c_str()
                               : "");
    std::printf("control    %s\n", field(s, "mode").c_str());
    const json& camera = s["camera"];
    std::printf("camera     %s: %s\n", camera.value("connected", false) ? "connected" : "NOT CONNECTED",
                field(camera, "status").c_str());
    const json& ptu = s["ptu"];
    std::printf("ptu        %s: pan %s deg (%s deg/s), tilt %s deg (%s deg/s)%s%s\n", field(ptu, "driver").c_str(),
                field(ptu, "pan_deg").c_str(), field(ptu, "pan_deg_s").c_str(), field(ptu, "tilt_deg").c_str(),
                field(ptu, "tilt_deg_s").c_str(), ptu.value("fault", false) ? ", FAULT: " : "",
                ptu.value("fault", false) ? field(ptu, "message").c_str() : "");
    const json& rt = s["realtime"];
    std::printf("realtime   priority %s; affinity %s; memory %s\n", field(rt, "priority").c_str(),
                field(rt, "affinity").c_str(), field(rt, "memory_lock").c_str());
    std::printf("uptime     %s s\n", field(s, "uptime_s").c_str());
}

void print_stats(const json& s) {
    for (const char* key : {"frames", "deadline_hits", "late_frames", "dropped_frames", "frame_timeouts",
                            "rejected_contours", "driver_errors", "telemetry_dropped", "log_dropped"})
        std::printf("%-18s %s\n", key, field(s, key).c_str());
    for (const char* key : {"loop_us", "track_us", "latency_us"})
        std::printf("%-18s median %s  p99 %s  max %s\n", key, field(s[key], "median").c_str(),
                    field(s[key], "p99").c_str(), field(s[key], "max").c_str());
}

void print_frame(const json& f) {
    std::printf("frame %s %s ref %s rays %s psr %s track %s us pan %s tilt %s\n", field(f, "frame").c_str(),
                field(f, "state").c_str(), field(f, "ref").c_str(), field(f, "rays").c_str(), field(f, "psr").c_str(),
                field(f, "track_us").c_str(), field(f, "pan_deg").c_str(), field(f, "tilt_deg").c_str());
}

}  // namespace

void print_reply(const json& reply, bool as_json) {
    if (as_json) {
        std::printf("%s\n", reply.dump().c_str());
        return;
    }
    std::string kind = reply.value("class", "");
    if (kind == "status") print_status(reply);
    else if (kind == "stats") print_stats(reply);
    else if (kind == "frame") print_frame(reply);
    else if (kind == "param") std::printf("%s = %s\n", field(reply, "name").c_str(), text(reply["value"]).c_str());
    else if (kind == "params")
        for (const auto& [name, value] : reply["values"].items()) std::printf("%s = %s\n", name.c_str(), text(value).c_str());
    else if (kind == "version")
        std::printf("raysd %s, protocol %s.%s\n", field(reply, "release").c_str(),
                    field(reply["protocol"], "major").c_str(), field(reply["protocol"], "minor").c_str());
    else if (kind == "error")
        std::fprintf(stderr, "raysctl: %s: %s\n", field(reply["error"], "code").c_str(),
                     field(reply["error"], "message").c_str());
    else if (kind == "ok") std::printf("ok\n");
    else std::printf("%s\n", reply.dump().c_str());
}

}  // namespace rays::ctl
