// SPDX-License-Identifier: Apache-2.0
// The named scenes: deterministic, long enough, with consistent truth, and each with the property
// it exists for (visible moving target, speed ramp, growth, occlusion, vanishing).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "scenes/scene.hpp"
#include "support/emulator.hpp"

using namespace rays;
using namespace rays::scenes;

namespace {

// All frames' truth and a per-frame summary of the mask, rendered once per scene.
struct FrameFacts {
    Truth truth;
    int mask_pixels = 0;
    bool touches_border = false;
    int mask_height = 0;  // rows from the mask's top to its bottom
};

std::vector<FrameFacts> facts_of(const Scene& scene) {
    std::vector<FrameFacts> facts;
    const auto f = std::make_unique<SceneFrame>();
    for (int i = 0; i < scene.frame_count(); ++i) {
        scene.render(i, *f);
        FrameFacts k{f->truth};
        int top = kFrameSize, bottom = -1;
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x)
                if (f->mask.at(x, y) != 0) {
                    ++k.mask_pixels;
                    k.touches_border |= x == 0 || y == 0 || x == kFrameSize - 1 || y == kFrameSize - 1;
                    top = std::min(top, y);
                    bottom = std::max(bottom, y);
                }
        k.mask_height = bottom - top + 1;
        facts.push_back(k);
    }
    return facts;
}

double step(const Truth& a, const Truth& b) { return std::hypot(b.cx - a.cx, b.cy - a.cy); }

}  // namespace

TEST_CASE("Every named scene exists once, renders deterministically and has at least 300 frames", "[scenes]") {
    std::set<std::string> seen;
    for (const auto name : scene_names()) {
        INFO(name);
        CHECK(seen.insert(std::string(name)).second);
        const auto scene = make_scene(name);
        REQUIRE(scene);
        CHECK(scene->name() == name);
        CHECK(!scene->description().empty());
        CHECK(scene->frame_count() >= 300);
        const auto a = std::make_unique<SceneFrame>(), b = std::make_unique<SceneFrame>(), c = std::make_unique<SceneFrame>();
        scene->render(123, *a);
        scene->render(7, *c);
        scene->render(123, *b);  // after another frame: random access gives the same frame
        CHECK(a->image.px == b->image.px);
        CHECK(a->mask.px == b->mask.px);
        CHECK(a->image.px != c->image.px);
        // A fresh instance of the scene draws the same frame too.
        make_scene(name)->render(123, *c);
        CHECK(a->image.px == c->image.px);
    }
    CHECK(seen.size() >= 11);
    CHECK(make_scene("no-such-scene") == nullptr);
    CHECK(make_scene("") == nullptr);
}

TEST_CASE("Each scene's truth matches its mask, targets stay in frame, visible and moving", "[scenes]") {
    rays::test::skip_under_emulation("every frame of every scene rendered; the single-scene cases render on arm64");
    for (const auto name : scene_names()) {
        INFO(name);
        const auto scene = make_scene(name);
        const auto facts = facts_of(*scene);
        const Point init = scene->init();
        CHECK(init.x == facts[0].truth.cx);
        CHECK(init.y == facts[0].truth.cy);
        int hidden = 0;
        for (std::size_t i = 0; i < facts.size(); ++i) {
            INFO("frame " << i);
            CHECK(facts[i].truth.area == facts[i].mask_pixels);
            CHECK(!facts[i].touches_border);
            if (facts[i].mask_pixels == 0) ++hidden;
            else CHECK(facts[i].mask_pixels >= 80);
        }
        CHECK(hidden == (name == "vanish" ? 40 : 0));
        // The tracker finds targets in frame differences: they move from the start.
        for (int i = 1; i <= 10; ++i) {
            INFO("frame " << i);
            CHECK(step(facts[i - 1].truth, facts[i].truth) >= 1.0);
        }
    }
}

TEST_CASE("vanish: the target is gone for frames 60-99 and comes back far from where it left", "[scenes]") {
    const auto facts = facts_of(*make_scene("vanish"));
    for (int i = 0; i < 60; ++i) CHECK(facts[i].mask_pixels > 0);
    for (int i = 60; i < 100; ++i) CHECK(facts[i].mask_pixels == 0);
    for (std::size_t i = 100; i < facts.size(); ++i) CHECK(facts[i].mask_pixels > 0);
    CHECK(step(facts[59].truth, facts[100].truth) > 40);
    CHECK(step(facts[100].truth, facts[101].truth) >= 1.0);
}

TEST_CASE("speed-ramp: speeds span 2 to 16 px/frame with at least 40 frames at a steady 8", "[scenes]") {
    const auto facts = facts_of(*make_scene("speed-ramp"));
    std::vector<double> step_x;
    for (std::size_t i = 1; i < facts.size(); ++i) step_x.push_back(facts[i].truth.cx - facts[i - 1].truth.cx);
    // A frame that turns at an edge shows a shorter net step: judge the speeds between the turns.
    double slowest = 1e9, fastest = 0;
    int longest_at_8 = 0, run_at_8 = 0;
    for (std::size_t i = 1; i + 1 < step_x.size(); ++i) {
        if ((step_x[i - 1] > 0) != (step_x[i + 1] > 0)) continue;  // turning
        const double speed = std::abs(step_x[i]);
        slowest = std::min(slowest, speed);
        fastest = std::max(fastest, speed);
        run_at_8 = std::abs(speed - 8.0) < 0.3 ? run_at_8 + 1 : 0;
        longest_at_8 = std::max(longest_at_8, run_at_8);
    }
    CHECK(slowest < 2.2);
    CHECK(slowest > 1.8);
    CHECK(fastest > 15.5);
    CHECK(fastest < 16.5);
    CHECK(longest_at_8 >= 40);
    CHECK(std::abs(facts.front().truth.cy - facts.back().truth.cy) < 0.5);  // purely horizontal
}

TEST_CASE("approach: the walker grows threefold in height and at least sixfold in area", "[scenes]") {
    const auto facts = facts_of(*make_scene("approach"));
    const FrameFacts& first = facts.front();
    const FrameFacts& last = facts.back();
    CHECK(first.mask_height == Approx(26).margin(2));
    CHECK(last.mask_height == Approx(77).margin(3));
    CHECK(last.mask_height >= 2.8 * first.mask_height);
    CHECK(last.truth.area >= 6 * first.truth.area);
    for (std::size_t i = 10; i < facts.size(); i += 10) CHECK(facts[i].mask_height >= facts[i - 10].mask_height);
}

TEST_CASE("occluder: the bar hides part of the target several times", "[scenes]") {
    const auto scene = make_scene("occluder");
    const auto facts = facts_of(*scene);
    const double full = std::max_element(facts.begin(), facts.end(), [](const FrameFacts& a, const FrameFacts& b) {
                            return a.truth.area < b.truth.area;
                        })->truth.area;
    int passes = 0;
    bool behind = false;
    for (const FrameFacts& k : facts) {
        const bool now = k.truth.area < 0.9 * full;
        passes += now && !behind;
        behind = now;
    }
    CHECK(passes >= 4);
    SceneFrame f;
    for (int i = 0; i < scene->frame_count(); i += 5) {
        scene->render(i, f);
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 61; x <= 67; ++x) REQUIRE(f.mask.at(x, y) == 0);
    }
}
