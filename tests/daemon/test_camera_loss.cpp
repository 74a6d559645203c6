// SPDX-License-Identifier: Apache-2.0
// When the camera goes away the axes stop, the status says so, and tracking resumes when it comes
// back: the V4L2 source on the fake kernel driver, and the capture thread and frame loop together
// on a scripted source, checked on the commands the simulated unit actually received.
#include <catch2/catch.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <thread>

#include "daemon/capture_thread.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/v4l2_source.hpp"
#include "drivers/mock/mock_ptu.hpp"
#include "fake_video_device.hpp"
#include "scenes/scene.hpp"
#include "support/eventually.hpp"
#include "test_frames.hpp"

namespace {

using namespace rays;
using namespace rays::daemon;
using namespace std::chrono_literals;

// A recorded scene as a live camera that the test can unplug and plug back in.
class UnpluggableSource final : public FrameSource {
public:
    UnpluggableSource() {
        auto scene = scenes::make_scene("clutter");
        auto rendered = std::make_unique<scenes::SceneFrame>();
        for (int i = 0; i < scene->frame_count(); ++i) {
            scene->render(i, *rendered);
            frames_.push_back(rendered->image);
        }
    }
    Result next(CapturedFrame& out, std::chrono::milliseconds) override {
        if (!plugged_) {
            std::this_thread::sleep_for(5ms);
            return reported_ ? Result::Timeout : (reported_ = true, Result::Disconnected);
        }
        reported_ = false;
        std::this_thread::sleep_for(10ms);  // 100 frames/s
        out.image = frames_[static_cast<std::size_t>(delivered_ % static_cast<long>(frames_.size()))];
        out.index = delivered_++;
        out.stamp = clock_.now();
        return Result::Frame;
    }
    bool live() const override { return true; }
    std::string describe() const override { return plugged_ ? "streaming" : "disconnected"; }
    std::atomic<bool> plugged_{true};

private:
    SteadyClock clock_;
    std::vector<GreyImage> frames_;
    long delivered_ = 0;
    bool reported_ = false;
};

double unit_speed(ptu::MockPtu& mock, const Clock& clock) {
    ptu::PtuState state;
    mock.read(state, clock.now());
    return std::hypot(state.axes[0].velocity_rad_s, state.axes[1].velocity_rad_s);
}

}  // namespace

TEST_CASE("a camera unplugged while tracking stops the axes until it is back") {
    SteadyClock clock;
    DaemonConfig config;
    LoopChannels channels(config.camera.queue_frames);
    ptu::MockPtu mock(ptu::MockPtuConfig{}, clock);
    ptu::PtuLimiter limiter(mock);
    REQUIRE(limiter.configure().ok);
    REQUIRE(limiter.activate().ok);
    ServiceNotifier notifier;
    FrameLoop loop(config, channels, limiter, notifier, clock);
    UnpluggableSource source;
    CaptureThread capture(source, channels, clock);
    capture.start();
    std::thread loop_thread([&] { loop.run(); });

    // Finding and following the target takes the loop a few frames, many more under the sanitizers on a
    // busy machine, so the test waits for the unit to move rather than a fixed time.
    auto moving = [&] { return unit_speed(mock, clock) > 0.05; };
    CHECK(test::eventually(moving));  // the target is found and followed
    CHECK(channels.camera_connected);

    source.plugged_ = false;
    auto status_says_away = [&] {
        bool away = false;
        channels.status.read([&](const LoopStatus& status) { away = !status.camera_connected; });
        return away;
    };
    CHECK(test::eventually([&] { return status_says_away() && unit_speed(mock, clock) == 0.0; }));
    CHECK_FALSE(channels.camera_connected);
    std::size_t records_when_stopped = mock.records().size();
    // The loop keeps writing while the camera is away...
    CHECK(test::eventually([&] { return mock.records().size() > records_when_stopped; }));
    auto since = mock.records().subspan(records_when_stopped);
    for (const ptu::CommandRecord& record : since)  // ...and every command is a stop
        for (const ptu::AxisCommand& axis : record.command.axes) {
            CHECK(axis.mode == ptu::CommandMode::Velocity);
            CHECK(axis.value == 0.0);
        }

    source.plugged_ = true;
    CHECK(test::eventually(moving));  // following the target again
    CHECK(channels.camera_connected);

    channels.stop = true;
    channels.frames.close();
    loop_thread.join();
    capture.stop(10s);  // returns once the thread has ended; a short grace could detach it when loaded
    CHECK(test::eventually([&] { return unit_speed(mock, clock) == 0.0; }));  // it ramps down at its own acceleration
}

TEST_CASE("the V4L2 source keeps kernel timestamps, reports an unplug once, and streams again after replug") {
    test::FakeClock clock;
    auto device = std::make_unique<test::FakeVideoDevice>(clock);
    test::FakeVideoDevice& fake = *device;
    CameraSettings settings;
    settings.source = "v4l2";
    std::string error;
    std::unique_ptr<V4l2Source> source = V4l2Source::open(settings, clock, error, std::move(device));
    REQUIRE(source);
    std::vector<std::uint8_t> frame = test::pack_grey(test::draw_pattern(640, 480));
    timeval stamp{1234, 500000};
    fake.push(test::FakeFrame{frame, {}, stamp, 0});
    CapturedFrame out;
    REQUIRE(source->next(out, 100ms) == FrameSource::Result::Frame);
    CHECK(out.index == 0);
    CHECK(out.stamp.time_since_epoch() == std::chrono::seconds(1234) + std::chrono::milliseconds(500));
    CHECK(out.image.px == test::area_scaled(test::draw_pattern(640, 480)).px);

    fake.unplug();
    CHECK(source->next(out, 100ms) == FrameSource::Result::Disconnected);
    CHECK(source->next(out, 100ms) == FrameSource::Result::Timeout);
    CHECK(source->describe().rfind("disconnected", 0) == 0);
    fake.replug({});
    FrameSource::Result result = FrameSource::Result::Timeout;
    for (int i = 0; i < 100 && result != FrameSource::Result::Frame; ++i) {
        fake.push(frame);
        result = source->next(out, 100ms);
    }
    CHECK(result == FrameSource::Result::Frame);
    CHECK(out.index == 1);
    CHECK(source->describe().rfind("streaming", 0) == 0);

    CameraSettings absent = settings;
    test::FakeClock other_clock;
    auto empty = std::make_unique<test::FakeVideoDevice>(other_clock);
    empty->unplug();
    CHECK_FALSE(V4l2Source::open(absent, other_clock, error, std::move(empty)));
    CHECK(error.rfind("/dev/video0: ", 0) == 0);
}
