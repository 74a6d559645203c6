// SPDX-License-Identifier: Apache-2.0
// rays-replay: runs the tracker over a recorded sequence and writes what it found as JSON Lines,
// optionally with overlay PNGs for a person to look at.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "config/tracker_config_io.hpp"
#include "core/tracker.hpp"
#include "frame_record.hpp"
#include "io/frame_reader.hpp"
#include "io/frame_scaler.hpp"
#include "io/overlay.hpp"
#include "io/png_writer.hpp"
#include "replay_options.hpp"

namespace {

constexpr int kOverlayZoom = 4;
constexpr int kOverlayRayStride = 8;  // draw every 8th ray

int fail(const std::string& message) {
    std::fprintf(stderr, "rays-replay: %s\n", message.c_str());
    return 1;
}

bool write_overlay(const std::string& dir, const rays::GreyImage& frame, const rays::Chroma& chroma,
                   const rays::Tracker& tracker, std::string& error) {
    using rays::io::Rgb;
    rays::io::RgbCanvas canvas(frame, chroma, kOverlayZoom);
    const rays::Contour& c = tracker.contour();
    if (tracker.result().has_contour) {
        for (int i = 0; i < c.size; i += kOverlayRayStride) canvas.line(c.ref, c.points[i].p, Rgb{60, 90, 200});
        std::vector<rays::Point> polygon(c.size);
        for (int i = 0; i < c.size; ++i) polygon[i] = c.points[i].p;
        canvas.polygon(polygon, Rgb{255, 40, 40});
        for (int i = 0; i < c.size; ++i)
            if (c.points[i].no_edge) canvas.dot(c.points[i].p, Rgb{255, 200, 0});
        canvas.cross(c.ref, 6, Rgb{40, 255, 40});
    }
    char name[64];
    std::snprintf(name, sizeof name, "/frame_%05ld.png", tracker.result().frame);
    return rays::io::write_png(dir + name, canvas.width(), canvas.height(), 3, canvas.rgb().data(), error);
}

}  // namespace

int main(int argc, char** argv) {
    std::string error;
    const auto options = rays::replay::parse_options(argc, argv, error);
    if (!options) {
        if (error.empty()) {
            std::fputs(rays::replay::usage(), stdout);
            return 0;
        }
        std::fprintf(stderr, "rays-replay: %s\n%s", error.c_str(), rays::replay::usage());
        return 2;
    }
    rays::TrackerConfig config;
    if (!options->config.empty()) {
        if (const auto e = rays::config::load_ini(options->config, config)) return fail(e->to_string());
    }
    auto opened = rays::io::open_frames(options->input);
    if (!opened.reader) return fail(opened.error);
    rays::io::FrameReader& reader = *opened.reader;
    const auto scaler = rays::io::FrameScaler::make(reader.width(), reader.height(), reader.chroma_width(),
                                                    reader.chroma_height(), options->crop, error);
    if (!scaler) return fail(error);
    if (!options->overlay_dir.empty()) {
        std::error_code ec;
        std::filesystem::create_directories(options->overlay_dir, ec);
        if (ec) return fail("cannot create " + options->overlay_dir + ": " + ec.message());
    }
    std::FILE* out = stdout;
    if (!options->out.empty() && !(out = std::fopen(options->out.c_str(), "w")))
        return fail("cannot write " + options->out);

    rays::SteadyClock clock;
    rays::Tracker tracker(config, clock);
    if (options->box) tracker.start_in(*options->box);  // parse_options checked it with box_problem()
    else if (options->init) tracker.start_at(*options->init);
    rays::replay::write_header(out, reader.width(), reader.height(), scaler->luma(), config, options->budget_us);

    rays::io::SourceImage source;
    rays::GreyImage frame;
    rays::Chroma chroma;
    std::vector<double> times;
    long tracking = 0, losses = 0;
    for (;;) {
        const auto status = reader.next(source);
        if (status == rays::io::FrameReader::Status::End) break;
        if (status == rays::io::FrameReader::Status::Error) {
            if (out != stdout) std::fclose(out);
            return fail(reader.error());
        }
        scaler->scale(source, frame, chroma);
        const auto start = rays::MonoClock::now();
        const auto deadline = options->budget_us > 0 ? start + std::chrono::microseconds(options->budget_us)
                                                     : rays::TimePoint::max();
        const rays::FrameResult& r = tracker.process(frame, chroma, deadline);
        const double us = std::chrono::duration<double, std::micro>(rays::MonoClock::now() - start).count();
        times.push_back(us);
        tracking += r.state == rays::TrackState::Tracking;
        losses += r.state == rays::TrackState::Lost;
        rays::replay::write_frame(out, tracker, us, options->crossings);
        if (!options->overlay_dir.empty() && !write_overlay(options->overlay_dir, frame, chroma, tracker, error)) {
            if (out != stdout) std::fclose(out);
            return fail(error);
        }
    }
    if (out != stdout && std::fclose(out) != 0) return fail("cannot finish writing " + options->out);
    if (times.empty()) return fail(options->input + ": no frames");
    std::sort(times.begin(), times.end());
    const auto pick = [&](double q) { return times[std::min(times.size() - 1, static_cast<size_t>(q * static_cast<double>(times.size())))]; };
    std::fprintf(stderr, "rays-replay: %zu frames, %ld tracking, %ld losses; time per frame median %.0f us, p99 %.0f us%s%s\n",
                 times.size(), tracking, losses, pick(0.5), pick(0.99),
                 options->overlay_dir.empty() ? "" : "; overlays in ", options->overlay_dir.c_str());
    return 0;
}
