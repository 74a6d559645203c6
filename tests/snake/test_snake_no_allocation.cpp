// SPDX-License-Identifier: Apache-2.0
// GreedySnakeTracker's per-frame path allocates nothing: allocations on the thread that calls
// process() are counted (support/thread_allocation_counter.hpp) while counting is switched on.
#include <catch2/catch.hpp>

#include "snake/greedy_snake_tracker.hpp"
#include "support/skip.hpp"
#include "support/tracker_allocation_run.hpp"

TEST_CASE("GreedySnakeTracker::process, set_tunables and a box start allocate nothing while tracking a scene", "[snake][no_allocation]") {
#ifdef RAYS_SANITIZED
    rays::test::skip(
        "allocation counting replaces malloc, which AddressSanitizer owns; runs in the Release configuration");
#else
    constexpr int kFrames = 200;
    const rays::TrackerConfig config;
    const rays::SteadyClock clock;
    rays::GreedySnakeTracker tracker(config, clock);
    // Differs in the point count (the snake is resampled), the window and the weights.
    rays::TrackerTunables changed = config.tunables;
    changed.snake.points = config.capacity.max_snake_points;
    changed.snake.neighbourhood = 7;
    changed.snake.beta *= 2.0;

    const rays::test::TrackerAllocationRun run = rays::test::count_tracker_allocations(tracker, "disc", kFrames, changed);
    CHECK(run.tunables_applied);
    CHECK(run.box_tracked);
    CHECK(tracker.contour().size == changed.snake.points);
    CHECK(run.allocations == 0);
    CHECK(run.tracking >= 100);
#endif
}
