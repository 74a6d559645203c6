// SPDX-License-Identifier: Apache-2.0
// The correlation filter (core/correlation_filter.hpp) on scenes drawn here
// (support/textured_filter_scene.hpp): a textured square on a differently textured background that
// pans, grey only and with colour.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>

#include "core/correlation_filter.hpp"
#include "support/textured_filter_scene.hpp"

namespace {

using rays::CorrelationFilter;
using rays::Point;

using rays::test::draw;
using rays::test::Images;
using rays::test::learned_on;
using rays::test::TexturedScene;

}  // namespace

TEST_CASE("The filter finds a textured target that moved on a panning textured background", "[filter]") {
    const bool colour = GENERATE(false, true);
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    f->chroma.present = colour;
    draw(scene, *f);
    auto filter = std::make_unique<CorrelationFilter>();
    CHECK_FALSE(filter->valid());
    CHECK(filter->locate(f->smoothed, f->chroma, scene.target).psr == 0.0);  // nothing learned yet
    filter->learn(f->smoothed, f->chroma, scene.target, 2.0 * TexturedScene::kHalf, 1.0f);
    REQUIRE(filter->valid());

    // Frame after frame the target moves 3 px right and 2 px down, the background 2 px left; the
    // filter looks round where the target was and learns where it finds it, from the same window.
    for (int frame = 1; frame <= 8; ++frame) {
        const Point was = scene.target;
        scene.target = {was.x + 3.0, was.y + 2.0};
        scene.pan = {scene.pan.x - 2.0, scene.pan.y};
        draw(scene, *f);
        const rays::FilterMatch match = filter->locate(f->smoothed, f->chroma, was);
        INFO("colour " << colour << ", frame " << frame << ": found at " << match.at.x << "," << match.at.y
                       << ", psr " << match.psr);
        CHECK(std::hypot(match.at.x - scene.target.x, match.at.y - scene.target.y) < 1.5);
        CHECK(match.psr > 8.0);
        filter->learn_located(f->smoothed, f->chroma, match.at, 2.0 * TexturedScene::kHalf, 0.02f);
    }
}

TEST_CASE("The filter's confidence collapses when the target is covered", "[filter]") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    auto filter = learned_on(scene, *f);

    scene.pan = {-3.0, 1.0};
    draw(scene, *f);
    const double seen = filter->locate(f->smoothed, f->chroma, scene.target).psr;
    draw(scene, *f, true);  // something the colour of the background in front of it
    const double covered = filter->locate(f->smoothed, f->chroma, scene.target).psr;
    INFO("psr seen " << seen << ", covered " << covered);
    CHECK(seen > 8.0);
    CHECK(covered < 0.5 * seen);
}

TEST_CASE("A filter's learned looks copied into another find the target as the original does, and stay as they were", "[filter]") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    auto filter = learned_on(scene, *f);
    auto copy = std::make_unique<CorrelationFilter>();
    copy->copy_learned(*filter);
    REQUIRE(copy->valid());
    CHECK(copy->window_px() == filter->window_px());

    scene.target = {scene.target.x + 3.0, scene.target.y - 2.0};
    scene.pan = {-2.0, 0.0};
    draw(scene, *f);
    const rays::FilterMatch a = filter->locate(f->smoothed, f->chroma, {48.0, 60.0});
    const rays::FilterMatch b = copy->locate(f->smoothed, f->chroma, {48.0, 60.0});
    CHECK(b.at.x == a.at.x);
    CHECK(b.at.y == a.at.y);
    CHECK(b.psr == a.psr);
    // The original learns something else (the background where the target was); the copy does not.
    filter->learn(f->smoothed, f->chroma, {20.0, 20.0}, 2.0 * TexturedScene::kHalf, 1.0f);
    const rays::FilterMatch c = copy->locate(f->smoothed, f->chroma, {48.0, 60.0});
    CHECK(c.psr == b.psr);
    CHECK(filter->locate(f->smoothed, f->chroma, {48.0, 60.0}).psr < b.psr);
}

TEST_CASE("The filter's window follows the target's size, within the frame", "[filter]") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    draw(scene, *f);
    CorrelationFilter filter;
    filter.learn(f->smoothed, f->chroma, scene.target, 20.0, 1.0f);
    CHECK(filter.window_px() == Approx(CorrelationFilter::kPadding * 20.0));
    filter.learn(f->smoothed, f->chroma, scene.target, 30.0, 0.5f);  // halfway to the new size
    CHECK(filter.window_px() == Approx(CorrelationFilter::kPadding * 25.0));
    filter.learn(f->smoothed, f->chroma, scene.target, 500.0, 1.0f);  // no window beyond the frame
    CHECK(filter.window_px() == Approx(rays::kFrameSize));
    filter.reset();
    CHECK_FALSE(filter.valid());
}

TEST_CASE("The filter does not find a target whose centre lies off the frame", "[filter]") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    auto filter = learned_on(scene, *f);

    // Its centre just inside the top of the frame: found there.
    scene.target = {48.0, 3.0};
    draw(scene, *f);
    const rays::FilterMatch inside = filter->locate(f->smoothed, f->chroma, {48.0, 12.0});
    INFO("centre in the frame: found at " << inside.at.x << "," << inside.at.y << ", psr " << inside.psr);
    CHECK(std::hypot(inside.at.x - scene.target.x, inside.at.y - scene.target.y) < 1.5);
    CHECK(inside.psr > 8.0);
    // Its centre above the frame, its lower part in view: the response peaks off the frame (without the
    // rule, at PSR 8.9), and that is not a find.
    scene.target = {48.0, -2.0};
    draw(scene, *f);
    const rays::FilterMatch beyond = filter->locate(f->smoothed, f->chroma, {48.0, 4.0});
    INFO("centre off the frame: found at " << beyond.at.x << "," << beyond.at.y << ", psr " << beyond.psr);
    CHECK(std::hypot(beyond.at.x - scene.target.x, beyond.at.y - scene.target.y) < 1.5);
    CHECK(beyond.psr == 0.0);
}
