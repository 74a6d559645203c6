// SPDX-License-Identifier: Apache-2.0
// The whole-frame search for a lost target's looks (core/frame_sweep.hpp) on the correlation
// filter's textured scene (support/textured_filter_scene.hpp): the target turns up far from where
// the filter learned it.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "core/frame_sweep.hpp"
#include "support/textured_filter_scene.hpp"

namespace {

using rays::FilterMatch;
using rays::FrameSweep;
using rays::Point;
using rays::test::draw;
using rays::test::Images;
using rays::test::learned_on;
using rays::test::TexturedScene;

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// The filter's window there is 50 px: a grid of 6 × 6 windows, 9 frames of 4 for the whole frame.
constexpr int kFramesPerSweep = 9;

}  // namespace

TEST_CASE("FrameSweep finds a target that turned up across the frame within one sweep, and not at once") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    auto filter = learned_on(scene, *f);  // at (48, 60)
    scene.target = {104.0, 22.0};
    draw(scene, *f);

    FrameSweep sweep;
    int found_in = 0;
    FilterMatch found;
    for (int frame = 1; frame <= kFramesPerSweep && found_in == 0; ++frame) {
        const FilterMatch m = sweep.next(*filter, f->smoothed, f->chroma);
        if (m.psr >= 8.0 && distance(m.at, scene.target) < 2.0) {
            found_in = frame;
            found = m;
        }
    }
    INFO("found in frame " << found_in << " at " << found.at.x << "," << found.at.y << ", psr " << found.psr);
    CHECK(found_in > 1);  // the first frame's four windows are in the top-left corner
    CHECK(found_in <= kFramesPerSweep);
}

TEST_CASE("FrameSweep starts from the frame's first window again after restart") {
    TexturedScene scene;
    auto f = std::make_unique<Images>();
    auto filter = learned_on(scene, *f);
    scene.target = {12.0, 12.0};  // in the grid's first window
    draw(scene, *f);

    FrameSweep sweep;
    const FilterMatch first = sweep.next(*filter, f->smoothed, f->chroma);
    CHECK(distance(first.at, scene.target) < 2.0);
    // Further on, the sweep looks elsewhere ...
    const FilterMatch later = sweep.next(*filter, f->smoothed, f->chroma);
    CHECK(distance(later.at, scene.target) > 10.0);
    // ... until a new loss starts it over.
    sweep.restart();
    const FilterMatch again = sweep.next(*filter, f->smoothed, f->chroma);
    CHECK(distance(again.at, scene.target) < 2.0);
    CHECK(again.psr == Approx(first.psr));
}
