// SPDX-License-Identifier: Apache-2.0
// A PTU fault seen by the frame loop: the axes get only stop commands, the status and the log say
// why, and control resumes when the unit recovers. Checked on what the simulated unit received.
#include <catch2/catch.hpp>

#include <thread>

#include "daemon/capture_thread.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/replay_source.hpp"
#include "captured_log.hpp"
#include "daemon_process.hpp"
#include "drivers/mock/mock_ptu.hpp"
#include "support/eventually.hpp"

namespace {

using namespace rays;
using namespace rays::daemon;
using namespace std::chrono_literals;

bool only_stops(std::span<const ptu::CommandRecord> records) {
    for (const ptu::CommandRecord& record : records)
        for (const ptu::AxisCommand& axis : record.command.axes)
            if (axis.mode != ptu::CommandMode::Velocity || axis.value != 0.0) return false;
    return true;
}

}  // namespace

TEST_CASE("a PTU fault stops the axes, is reported in status and log, and control resumes after it clears") {
    std::filesystem::path dir = test::fresh_dir("ptu-fault");
    test::write_test_sequence(dir / "seq.y4m", 100);
    SteadyClock clock;
    DaemonConfig config;
    config.camera.source = "replay";
    config.camera.replay_path = (dir / "seq.y4m").string();
    config.camera.replay_loop = true;
    // A replayed picture does not turn with the unit: the predictive law's world model would not
    // hold, so the paper's proportional law steers here.
    config.control.law = "proportional";
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
    auto status = [&] {
        LoopStatus copy;
        channels.status.read([&](const LoopStatus& s) { copy = s; });
        return copy;
    };

    REQUIRE(test::eventually([&] { return status().last.state == TrackState::Tracking; }));
    CHECK_FALSE(status().ptu_fault);

    mock.inject_fault(ptu::Axis::Tilt, "overcurrent");
    REQUIRE(test::eventually([&] { return status().ptu_fault; }));
    LoopStatus faulted = status();
    CHECK(std::string(faulted.ptu_message.data()) == "mock: tilt axis fault: overcurrent");
    CHECK(faulted.stats.driver_errors > 0);
    // Once the limiter has ramped the last motion down (at its deceleration limit):
    REQUIRE(test::eventually([&] {
        const auto records = mock.records();
        return !records.empty() && only_stops(records.last(1));
    }));
    const std::size_t at_fault = mock.records().size();
    CHECK(test::eventually([&] { return mock.records().size() > at_fault + 5; }));  // the loop keeps commanding...
    CHECK(only_stops(mock.records().subspan(at_fault)));  // ...nothing but stops
    ptu::PtuState unit;
    mock.read(unit, clock.now());
    CHECK(unit.axes[0].velocity_rad_s == 0.0);  // the healthy axis was stopped too
    CHECK(unit.axes[1].velocity_rad_s == 0.0);

    mock.clear_fault();
    CHECK(test::eventually([&] { return !status().ptu_fault; }));
    CHECK(test::eventually([&] {  // following again
        mock.read(unit, clock.now());
        return std::abs(unit.axes[0].velocity_rad_s) + std::abs(unit.axes[1].velocity_rad_s) > 0.0;
    }));

    channels.stop = true;
    channels.frames.close();
    loop_thread.join();
    capture.stop(10s);  // returns once the thread has ended; a short grace could detach it when loaded
    // The frame loop's log lines, as the socket thread would write them.
    test::CapturedLog log;
    channels.log.drain();
    CHECK(log.text().find("<3>PTU driver fault, axes stopped: mock: tilt axis fault: overcurrent") != std::string::npos);
    CHECK(log.text().find("<5>PTU driver recovered") != std::string::npos);
}
