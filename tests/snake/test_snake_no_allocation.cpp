// GreedySnakeTracker's per-frame path allocates nothing: allocations on the thread that calls
// process() are counted (support/thread_allocation_counter.hpp) while counting is switched on.
#include <catch2/catch.hpp>

#include <chrono>
#include <memory>
#include <vector>

#include "scenes/scene.hpp"
#include "snake/greedy_snake_tracker.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"

TEST_CASE("GreedySnakeTracker::process and set_tunables allocate nothing while tracking a scene", "[snake][no_allocation]") {
#ifdef RAYS_SANITIZED
    rays::test::skip(
        "allocation counting replaces malloc, which AddressSanitizer owns; runs in the Release configuration");
#else
    using rays::test::counted_allocations;
    using rays::test::CountingScope;
    constexpr int kFrames = 200;
    const rays::TrackerConfig config;
    const rays::SteadyClock clock;
    rays::GreedySnakeTracker tracker(config, clock);
    // Differs in the point count (the snake is resampled), the window and the weights.
    rays::TrackerTunables changed = config.tunables;
    changed.snake.points = config.capacity.max_snake_points;
    changed.snake.neighbourhood = 7;
    changed.snake.beta *= 2.0;

    auto scene = rays::scenes::make_scene("disc");
    REQUIRE(scene != nullptr);
    REQUIRE(scene->frame_count() >= kFrames);
    std::vector<rays::GreyImage> frames(kFrames);
    {
        const auto rendered = std::make_unique<rays::scenes::SceneFrame>();
        for (int i = 0; i < kFrames; ++i) {
            scene->render(i, *rendered);
            frames[static_cast<std::size_t>(i)] = rendered->image;
        }
    }

    const rays::TimePoint deadline = clock.now() + std::chrono::hours(1);
    int tracking = 0;
    bool tunables_applied = false;
    long allocations = 0;
    {
        CountingScope counting;
        for (int i = 0; i < kFrames; ++i) {
            if (i == kFrames / 2) tunables_applied = tracker.set_tunables(changed);
            if (tracker.process(frames[static_cast<std::size_t>(i)], deadline).state == rays::TrackState::Tracking)
                ++tracking;
        }
        allocations = counted_allocations();
    }
    CHECK(tunables_applied);
    CHECK(tracker.contour().size == changed.snake.points);
    CHECK(allocations == 0);
    CHECK(tracking >= 100);
#endif
}
