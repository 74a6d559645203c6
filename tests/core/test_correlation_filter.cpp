// SPDX-License-Identifier: Apache-2.0
// The correlation filter (core/correlation_filter.hpp) on scenes drawn here: a textured square on a
// differently textured background that pans, grey only and with colour. Its edges are everywhere;
// only its looks tell it apart.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>

#include "core/correlation_filter.hpp"
#include "core/gaussian_smoother.hpp"
#include "support/block_texture.hpp"

namespace {

using rays::Chroma;
using rays::CorrelationFilter;
using rays::FloatImage;
using rays::GreyImage;
using rays::Point;

using rays::test::block_hash;
using rays::test::floor_div;

// Background: 4-px blocks of random grey 40…200, moving with the pan. Target: a 20-px square of
// 3-px blocks of its own texture, moving with itself; `covered`: the background shows where it is.
struct TexturedScene {
    static constexpr int kHalf = 10;
    Point target{48.0, 60.0};
    Point pan;  // the background's offset

    void render(GreyImage& luma, Chroma& chroma, bool covered = false) const {
        const int bx = static_cast<int>(std::lround(pan.x)), by = static_cast<int>(std::lround(pan.y));
        const int tx = static_cast<int>(std::lround(target.x)), ty = static_cast<int>(std::lround(target.y));
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                const bool on = !covered && std::abs(x - tx) <= kHalf && std::abs(y - ty) <= kHalf;
                luma.at(x, y) = on ? static_cast<std::uint8_t>(40 + block_hash(floor_div(x - tx, 3), floor_div(y - ty, 3), 7u) % 161)
                                   : static_cast<std::uint8_t>(40 + block_hash(floor_div(x - bx, 4), floor_div(y - by, 4), 1u) % 161);
            }
        for (int j = 0; j < rays::kChromaSize; ++j)
            for (int i = 0; i < rays::kChromaSize; ++i) {
                const int x = 2 * i, y = 2 * j;
                const bool on = !covered && std::abs(x - tx) <= kHalf && std::abs(y - ty) <= kHalf;
                const std::uint32_t h = block_hash(floor_div(x - bx, 8), floor_div(y - by, 8), 3u);
                const auto k = static_cast<std::size_t>(j * rays::kChromaSize + i);
                chroma.u[k] = static_cast<std::uint8_t>(on ? 100 + h % 10 : 110 + h % 40);
                chroma.v[k] = static_cast<std::uint8_t>(on ? 170 + h % 10 : 100 + h % 40);
            }
    }
};

struct Images {
    GreyImage luma;
    Chroma chroma;
    FloatImage smoothed;
};

// Draws the scene and smooths it as the tracker does.
void draw(const TexturedScene& scene, Images& f, bool covered = false) {
    scene.render(f.luma, f.chroma, covered);
    rays::GaussianSmoother smoother;
    smoother.set_sigma(1.0);
    smoother.smooth(f.luma, f.smoothed);
}

// The scene drawn in colour, and a new filter learned on its target.
std::unique_ptr<CorrelationFilter> learned_on(const TexturedScene& scene, Images& f) {
    f.chroma.present = true;
    draw(scene, f);
    auto filter = std::make_unique<CorrelationFilter>();
    filter->learn(f.smoothed, f.chroma, scene.target, 2.0 * TexturedScene::kHalf, 1.0f);
    return filter;
}

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
