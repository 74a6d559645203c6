// SPDX-License-Identifier: Apache-2.0
#include "daemon/request_handler.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/angles.hpp"
#include "config/config_engine.hpp"
#include "daemon/base64.hpp"
#include "daemon/daemon_params.hpp"
#include "daemon/log.hpp"
#include "io/overlay.hpp"
#include "io/png_writer.hpp"

#ifndef RAYS_VERSION
#define RAYS_VERSION "unknown"
#endif

namespace rays::daemon {
namespace {

using nlohmann::json;

constexpr int kSnapshotZoom = 4;
// Copying and printing a JSON value recurse once per level: a deeper "id" overflowed the stack.
constexpr int kMaxRequestDepth = 64;

json ok(std::string_view name) { return {{"class", "ok"}, {"cmd", name}}; }

// The number in `request[key]`, or nullopt when absent or not a finite number.
std::optional<double> number_field(const json& request, const char* key) {
    auto found = request.find(key);
    if (found == request.end() || !found->is_number()) return std::nullopt;
    double value = found->get<double>();
    if (!std::isfinite(value)) return std::nullopt;
    return value;
}

json missing_number(const char* key, std::string_view name) {
    return RequestHandler::error("bad_request", std::string(name) + " needs a number \"" + key + "\"");
}

json time_summary(const std::array<float, kRecentFrames>& recent, long frames) {
    std::size_t n = static_cast<std::size_t>(std::min<long>(frames, kRecentFrames));
    if (n == 0) return {{"median", nullptr}, {"p99", nullptr}, {"max", nullptr}};
    std::vector<float> sorted(recent.begin(), recent.begin() + static_cast<std::ptrdiff_t>(n));
    std::sort(sorted.begin(), sorted.end());
    auto at = [&](double q) { return sorted[std::min(n - 1, static_cast<std::size_t>(q * static_cast<double>(n)))]; };
    return {{"median", at(0.5)}, {"p99", at(0.99)}, {"max", sorted.back()}};
}

json value_of(const config::ParamValue& value) {
    return std::visit([](const auto& v) { return json(v); }, value);
}

}  // namespace

RequestHandler::RequestHandler(DaemonConfig& config, LoopChannels& channels, DaemonFacts facts,
                               std::function<std::string()> camera_status, const Clock& clock)
    : config_(config),
      channels_(channels),
      facts_(std::move(facts)),
      camera_status_(std::move(camera_status)),
      clock_(clock) {}

json RequestHandler::banner() {
    return {{"class", "version"},
            {"release", RAYS_VERSION},
            {"protocol", {{"major", kProtocolMajor}, {"minor", kProtocolMinor}}}};
}

json RequestHandler::error(std::string_view code, std::string_view message) {
    return {{"class", "error"}, {"error", {{"code", code}, {"message", message}}}};
}

json RequestHandler::handle(std::string_view line, ClientSession& session) {
    bool too_deep = false;
    auto limit_depth = [&](int depth, json::parse_event_t, json&) {  // depth 0: the request itself
        if (depth >= kMaxRequestDepth) too_deep = true;
        return depth < kMaxRequestDepth;  // false: the parser does not build the deeper value
    };
    json request = json::parse(line, limit_depth, false);
    if (request.is_discarded()) return error("bad_json", "the request is not valid JSON");
    if (too_deep)
        return error("bad_request", "a request is nested at most " + std::to_string(kMaxRequestDepth) + " levels deep");
    if (!request.is_object()) return error("bad_request", "a request is a JSON object");
    json reply = dispatch(request, session);
    if (auto id = request.find("id"); id != request.end()) reply["id"] = *id;
    return reply;
}

json RequestHandler::dispatch(const json& request, ClientSession& session) {
    auto cmd = request.find("cmd");
    if (cmd == request.end() || !cmd->is_string()) return error("bad_request", "a request needs a \"cmd\" string");
    const std::string& name = cmd->get_ref<const std::string&>();
    if (name == "version") return banner();
    if (name == "status") return status();
    if (name == "stats") return stats();
    if (name == "get") return get(request);
    if (name == "set") return set(request);
    if (name == "track") return track(request);
    if (name == "release") return send(make_command(CommandKind::Release), name);
    if (name == "reinit") return send(make_command(CommandKind::Reinit), name);
    if (name == "resume") return send(make_command(CommandKind::Resume), name);
    if (name == "ptu") return ptu(request);
    if (name == "snapshot") return snapshot();
    if (name == "watch") return watch(request, session);
    return error("unknown_command", "unknown command '" + name + "'");
}

json RequestHandler::send(const LoopCommand& command, std::string_view name) {
    if (!channels_.commands.push(command)) return error("busy", "the frame loop's command queue is full; try again");
    return ok(name);
}

bool RequestHandler::push_tunables() {
    Priority level = Priority::Info;
    if (parse_priority(config_.log.level, level)) set_log_level(level);
    set_log_repeat_interval(std::chrono::duration<double>(config_.log.repeat_interval_s));
    LoopCommand command = make_command(CommandKind::Tunables);
    command.tunables = loop_tunables(config_);
    return channels_.commands.push(command);
}

json RequestHandler::status() const {
    json reply;
    channels_.status.read([&](const LoopStatus& s) {
        const FrameTelemetry& f = s.last;
        reply = {{"class", "status"},
                 {"state", to_string(f.state)},
                 {"frame", f.frame},
                 {"ref", f.has_contour ? json::array({f.ref_x, f.ref_y}) : json(nullptr)},
                 {"area_px", f.area_px},
                 {"mode", to_string(s.mode)},
                 {"running", s.running}};
        reply["ptu"] = {{"driver", facts_.driver},
                        {"pan_deg", s.ptu.axes[0].position_rad / kRadPerDeg},
                        {"tilt_deg", s.ptu.axes[1].position_rad / kRadPerDeg},
                        {"pan_deg_s", s.ptu.axes[0].velocity_rad_s / kRadPerDeg},
                        {"tilt_deg_s", s.ptu.axes[1].velocity_rad_s / kRadPerDeg},
                        {"enabled", s.ptu.axes[0].enabled && s.ptu.axes[1].enabled},
                        {"fault", s.ptu_fault || s.ptu.axes[0].fault || s.ptu.axes[1].fault},
                        {"message", s.ptu_message.data()}};
        reply["camera"] = {{"connected", s.camera_connected}};
    });
    reply["camera"]["status"] = camera_status_();
    reply["uptime_s"] = std::chrono::duration<double>(clock_.now() - facts_.started).count();
    reply["realtime"] = {
        {"priority", facts_.priority}, {"affinity", facts_.affinity}, {"memory_lock", facts_.memory_lock}};
    return reply;
}

json RequestHandler::stats() const {
    json reply;
    channels_.status.read([&](const LoopStatus& s) {
        const LoopStats& st = s.stats;
        json histogram = json::array();
        for (int i = 0; i < kHistogramBins; ++i) {
            float edge = kHistogramEdgesUs[static_cast<std::size_t>(i)];
            histogram.push_back({{"below_us", i + 1 < kHistogramBins ? json(edge) : json(nullptr)},
                                 {"count", st.loop_histogram[static_cast<std::size_t>(i)]}});
        }
        reply = {{"class", "stats"},
                 {"frames", st.frames},
                 {"deadline_hits", st.deadline_hits},
                 {"late_frames", st.late_frames},
                 {"frame_timeouts", st.frame_timeouts},
                 {"rejected_contours", st.rejected_contours},
                 {"driver_errors", st.driver_errors},
                 {"telemetry_dropped", st.telemetry_dropped},
                 {"loop_us", time_summary(st.recent_loop_us, st.frames)},
                 {"track_us", time_summary(st.recent_track_us, st.frames)},
                 {"latency_us", time_summary(st.recent_latency_us, st.frames)},
                 {"loop_histogram", std::move(histogram)}};
    });
    reply["dropped_frames"] = channels_.frames.dropped();
    reply["log_dropped"] = channels_.log.dropped();
    return reply;
}

json RequestHandler::get(const json& request) const {
    auto name = request.find("name");
    if (name == request.end()) return {{"class", "params"}, {"values", config::to_json(daemon_params(), config_)}};
    if (!name->is_string()) return error("bad_request", "get: \"name\" is a string");
    const auto* param = daemon_params().find(name->get_ref<const std::string&>());
    if (param == nullptr) {
        std::string ignored;
        return error("bad_param", *config::get_param(daemon_params(), config_, name->get<std::string>(), ignored));
    }
    return {{"class", "param"},
            {"name", param->info.name},
            {"value", value_of(param->read(config_))},
            {"kind", param->info.kind == config::ParamKind::Capacity ? "capacity" : "tunable"}};
}

json RequestHandler::set(const json& request) {
    auto name = request.find("name");
    auto value = request.find("value");
    if (name == request.end() || !name->is_string() || value == request.end())
        return error("bad_request", "set needs a \"name\" string and a \"value\"");
    std::string text;
    if (value->is_string()) text = value->get<std::string>();
    else if (value->is_number() || value->is_boolean()) text = value->dump();
    else return error("bad_request", "set: \"value\" is a number, a boolean or a string");
    DaemonConfig candidate = config_;
    if (auto problem = config::set_param(daemon_params(), candidate, name->get<std::string>(), text, false))
        return error("bad_param", *problem);
    DaemonConfig previous = config_;
    config_ = candidate;
    if (!push_tunables()) {
        config_ = previous;
        return error("busy", "the frame loop's command queue is full; try again");
    }
    log(Priority::Info, "set %s = %s", name->get_ref<const std::string&>().c_str(), text.c_str());
    json reply = get(json{{"name", *name}});
    return reply;
}

json RequestHandler::track(const json& request) {
    std::optional<double> x = number_field(request, "x");
    std::optional<double> y = number_field(request, "y");
    if (!x) return missing_number("x", "track");
    if (!y) return missing_number("y", "track");
    const bool has_w = request.contains("w"), has_h = request.contains("h");
    if (has_w || has_h) {  // a box: (x, y) its top-left corner
        if (!has_w || !has_h) return error("bad_request", "track: a box needs both \"w\" and \"h\"");
        std::optional<double> w = number_field(request, "w");
        std::optional<double> h = number_field(request, "h");
        if (!w) return missing_number("w", "track");
        if (!h) return missing_number("h", "track");
        const Box box{*x, *y, *w, *h};
        if (const char* problem = box_problem(box)) return error("bad_request", std::string("track: ") + problem);
        return send(make_box_command(box), "track");
    }
    if (*x < 0 || *x > kFrameSize - 1 || *y < 0 || *y > kFrameSize - 1)
        return error("bad_request", "track: x and y are processing pixels in [0, 127]");
    return send(make_command(CommandKind::Track, *x, *y), "track");
}

json RequestHandler::ptu(const json& request) {
    auto action = request.find("action");
    if (action == request.end() || !action->is_string())
        return error("bad_request", "ptu needs an \"action\": jog, goto, stop, home or park");
    const std::string& what = action->get_ref<const std::string&>();
    if (what == "jog") {
        std::optional<double> pan = number_field(request, "pan_deg_s");
        std::optional<double> tilt = number_field(request, "tilt_deg_s");
        if (!pan) return missing_number("pan_deg_s", "ptu jog");
        if (!tilt) return missing_number("tilt_deg_s", "ptu jog");
        return send(make_command(CommandKind::Jog, *pan * kRadPerDeg, *tilt * kRadPerDeg), "ptu");
    }
    if (what == "goto") {
        std::optional<double> pan = number_field(request, "pan_deg");
        std::optional<double> tilt = number_field(request, "tilt_deg");
        if (!pan) return missing_number("pan_deg", "ptu goto");
        if (!tilt) return missing_number("tilt_deg", "ptu goto");
        return send(make_command(CommandKind::Goto, *pan * kRadPerDeg, *tilt * kRadPerDeg), "ptu");
    }
    if (what == "stop") return send(make_command(CommandKind::Stop), "ptu");
    if (what == "home") return send(make_command(CommandKind::Home), "ptu");
    if (what == "park") return send(make_command(CommandKind::Park), "ptu");
    return error("bad_request", "ptu: unknown action '" + what + "' (jog, goto, stop, home or park)");
}

json RequestHandler::snapshot() const {
    SnapshotFrame snap;  // not on the frame loop's thread: a copy here is fine
    channels_.snapshot.read([&](const SnapshotFrame& latest) {
        snap.frame = latest.frame;
        snap.image = latest.image;
        snap.chroma = latest.chroma;
        snap.has_contour = latest.has_contour;
        snap.ref = latest.ref;
        snap.points = latest.points;
        std::copy_n(latest.contour.begin(), latest.points, snap.contour.begin());
    });
    if (snap.frame < 0) return error("not_available", "no frame has been processed yet");
    io::RgbCanvas canvas(snap.image, snap.chroma, kSnapshotZoom);
    if (snap.has_contour) {
        canvas.polygon(std::vector<Point>(snap.contour.begin(), snap.contour.begin() + snap.points), {0, 255, 0});
        canvas.cross(snap.ref, 6, {255, 0, 0});
    }
    std::vector<std::uint8_t> png;
    if (!io::encode_png(canvas.width(), canvas.height(), 3, canvas.rgb().data(), png))
        return error("not_available", "PNG encoding failed");
    return {{"class", "snapshot"},
            {"frame", snap.frame},
            {"width", canvas.width()},
            {"height", canvas.height()},
            {"format", "png"},
            {"data", base64_encode(png)}};
}

json RequestHandler::watch(const json& request, ClientSession& session) {
    auto enable = request.find("enable");
    if (enable != request.end() && !enable->is_boolean()) return error("bad_request", "watch: \"enable\" is a boolean");
    session.watching = enable == request.end() || enable->get<bool>();
    return {{"class", "watch"}, {"enable", session.watching}};
}

json frame_record(const FrameTelemetry& f) {
    return {{"class", "frame"},
            {"frame", f.frame},
            {"time_s", f.time_s},
            {"state", to_string(f.state)},
            {"ref", f.has_contour ? json::array({f.ref_x, f.ref_y}) : json(nullptr)},
            {"area_px", f.area_px},
            {"rays", f.rays},
            {"levels", f.levels},
            {"deadline_hit", f.deadline_hit},
            {"psr", f.psr},
            {"track_us", f.track_us},
            {"loop_us", f.loop_us},
            {"latency_us", f.latency_us},
            {"mode", to_string(f.mode)},
            {"pan_deg", f.pan_deg},
            {"tilt_deg", f.tilt_deg},
            {"pan_cmd_deg_s", f.pan_cmd_deg_s},
            {"tilt_cmd_deg_s", f.tilt_cmd_deg_s}};
}

}  // namespace rays::daemon
