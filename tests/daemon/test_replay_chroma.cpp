// SPDX-License-Identifier: Apache-2.0
// The frame the loop receives from a replayed colour stream carries its chroma through the queue; a
// mono stream's carries none.
#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "core/clock.hpp"
#include "daemon/frame_queue.hpp"
#include "daemon/replay_source.hpp"
#include "daemon_process.hpp"

using namespace rays;
using namespace rays::daemon;
using namespace std::chrono_literals;

namespace {

CapturedFrame replay_first(const std::filesystem::path& path) {
    CameraSettings settings;
    settings.source = "replay";
    settings.replay_path = path.string();
    SteadyClock clock;
    std::string error;
    auto source = ReplaySource::open(settings, clock, error);
    INFO(error);
    REQUIRE(source);
    CapturedFrame captured;
    REQUIRE(source->next(captured, 1s) == FrameSource::Result::Frame);
    FrameQueue queue(2);  // through the hand-over to the frame loop
    REQUIRE(queue.push(captured, true, 1s) == FrameQueue::Push::Queued);
    CapturedFrame delivered;
    REQUIRE(queue.pop(delivered, 1s));
    return delivered;
}

}  // namespace

TEST_CASE("a replayed 4:2:0 stream's chroma reaches the frame loop, a mono stream's is absent") {
    const std::filesystem::path dir = test::fresh_dir("replay-chroma");
    {
        std::ofstream out(dir / "colour.y4m", std::ios::binary);
        out << "YUV4MPEG2 W128 H128 F25:1 C420jpeg\nFRAME\n" << std::string(128 * 128, '\x64')
            << std::string(64 * 64, '\x50') << std::string(64 * 64, '\xb4');
    }
    const CapturedFrame colour = replay_first(dir / "colour.y4m");
    REQUIRE(colour.chroma.present);
    CHECK(colour.image.at(3, 3) == 0x64);
    CHECK(colour.chroma.u_at(10, 20) == 0x50);
    CHECK(colour.chroma.v_at(63, 0) == 0xb4);

    test::write_test_sequence(dir / "mono.y4m", 2);  // Y4mWriter writes Cmono
    CHECK_FALSE(replay_first(dir / "mono.y4m").chroma.present);
}
