// SPDX-License-Identifier: Apache-2.0
// make_tracker picks the contour tracker that track.method names.
#include <catch2/catch.hpp>

#include <string>

#include "core/tracker.hpp"
#include "snake/greedy_snake_tracker.hpp"
#include "snake/tracker_factory.hpp"

TEST_CASE("make_tracker returns the tracker of the configured method", "[snake][factory]") {
    const rays::SteadyClock clock;
    rays::TrackerConfig config;
    CHECK(config.method == rays::TrackerMethod::Rays);  // active rays unless configured otherwise

    const auto rays_tracker = rays::make_tracker(config, clock);
    REQUIRE(rays_tracker != nullptr);
    CHECK(std::string(rays_tracker->method()) == "rays");
    CHECK(dynamic_cast<rays::Tracker*>(rays_tracker.get()) != nullptr);

    config.method = rays::TrackerMethod::Snake;
    config.capacity.max_snake_points = 64;
    const auto snake_tracker = rays::make_tracker(config, clock);
    REQUIRE(snake_tracker != nullptr);
    CHECK(std::string(snake_tracker->method()) == "snake");
    const auto* snake = dynamic_cast<rays::GreedySnakeTracker*>(snake_tracker.get());
    REQUIRE(snake != nullptr);
    CHECK(snake->capacity().max_snake_points == 64);
    CHECK(snake->snake().capacity() == 64);
}
