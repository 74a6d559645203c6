// SPDX-License-Identifier: Apache-2.0
// A user's track request takes over at once: the frame loop drops the target it tracks and starts
// where it is told, from the next frame on, not once the old target is lost.
#include <catch2/catch.hpp>

#include <cmath>
#include <thread>

#include "daemon/capture_thread.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/replay_source.hpp"
#include "daemon_process.hpp"
#include "drivers/mock/mock_ptu.hpp"
#include "drivers/ptu_limiter.hpp"
#include "io/y4m_writer.hpp"
#include "support/eventually.hpp"

using namespace rays;
using namespace rays::daemon;
using namespace std::chrono_literals;

namespace {

constexpr Point kStill{32.0, 40.0};  // a disc that never moves: detection never finds it

// A bright disc crossing left to right at y = 90 beside a still one, on a flat background.
void write_two_discs(const std::filesystem::path& path, int frames) {
    io::Y4mWriter writer;
    REQUIRE(writer.open(path.string(), kFrameSize, kFrameSize, 25, 1));
    GreyImage image;
    for (int f = 0; f < frames; ++f) {
        const Point mover{20.0 + f % 80, 90.0};
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const bool in = std::hypot(x - mover.x, y - mover.y) < 10.0 || std::hypot(x - kStill.x, y - kStill.y) < 10.0;
                image.at(x, y) = in ? 200 : 90;
            }
        REQUIRE(writer.write(image.px.data()));
    }
}

}  // namespace

TEST_CASE("track while tracking moves the track to the new start on the next frames") {
    const std::filesystem::path dir = test::fresh_dir("track-command");
    write_two_discs(dir / "seq.y4m", 80);
    SteadyClock clock;
    DaemonConfig config;
    config.camera.source = "replay";
    config.camera.replay_path = (dir / "seq.y4m").string();
    config.camera.replay_loop = true;
    config.control.law = "proportional";  // a replay does not turn with the unit
    std::string error;
    auto source = ReplaySource::open(config.camera, clock, error);
    REQUIRE(source);
    LoopChannels channels(config.camera.queue_frames);
    ptu::MockPtu mock(ptu::MockPtuConfig{}, clock);
    ptu::PtuLimiter limiter(mock);
    REQUIRE(limiter.configure().ok);
    REQUIRE(limiter.activate().ok);
    ServiceNotifier notifier;
    FrameLoop loop(config, channels, limiter, notifier, clock);
    CaptureThread capture(*source, channels, clock);
    capture.start();
    std::thread loop_thread([&] { loop.run(); });

    // Every frame's record, as the socket thread would take them.
    FrameTelemetry last;
    const auto drain_until = [&](auto done) {
        return test::eventually([&] {
            for (FrameTelemetry t; channels.telemetry.pop(t);)
                if (done(t)) return last = t, true;
            return false;
        });
    };
    REQUIRE(drain_until([](const FrameTelemetry& t) { return t.state == TrackState::Tracking; }));
    INFO("tracking the mover at " << last.ref_x << "," << last.ref_y);
    REQUIRE(last.ref_y > 70.0);  // the mover, found by its motion
    const long told_at = last.frame;
    REQUIRE(channels.commands.push(make_command(CommandKind::Track, kStill.x, kStill.y)));
    // The first contour a frame after the command is on the still disc, while the mover is in plain view.
    CHECK(drain_until([&](const FrameTelemetry& t) { return t.frame > told_at + 1 && t.has_contour; }));
    CHECK(std::hypot(last.ref_x - kStill.x, last.ref_y - kStill.y) < 4.0);

    channels.stop = true;
    channels.frames.close();
    loop_thread.join();
    capture.stop(10s);
}
