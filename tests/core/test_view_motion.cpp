// SPDX-License-Identifier: Apache-2.0
// Whether the view moved (core/view_motion.hpp), on views drawn here: a blocky textured world seen
// still, panning (fast, and slower than a still view's bound), with a crowd crossing it, with a target
// the camera follows, in changing light; and the previous frame aligned by the view's shift.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/view_motion.hpp"
#include "support/block_texture.hpp"

namespace {

using rays::FloatImage;
using rays::ViewMotion;
using rays::ViewShift;
using rays::test::smooth_blocks;

// The view of the world from `pan` (the view at x shows the world at x + pan), with `gain` and
// `offset` for the light.
void view(FloatImage& out, rays::Point pan, double gain = 1.0, double offset = 0.0) {
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x)
            out.at(x, y) = static_cast<float>(gain * smooth_blocks(x + pan.x, y + pan.y, 1u) + offset);
}

// Paints a textured box of its own texture, moving with it, over [x0, x0 + w) × [y0, y0 + h).
void paint_mover(FloatImage& out, double x0, double y0, int w, int h, unsigned seed) {
    for (int y = std::max(0, static_cast<int>(y0)); y < std::min(rays::kFrameSize, static_cast<int>(y0) + h); ++y)
        for (int x = std::max(0, static_cast<int>(x0)); x < std::min(rays::kFrameSize, static_cast<int>(x0) + w); ++x)
            out.at(x, y) = static_cast<float>(smooth_blocks(x - x0, y - y0, seed));
}

ViewShift measure(ViewMotion& motion, const FloatImage& image) {
    motion.take(image);
    return motion.since_previous();
}

}  // namespace

TEST_CASE("The first frame's view motion is unknown, and a still textured view is still", "[view]") {
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    view(*image, {0.0, 0.0});
    const ViewShift first = measure(motion, *image);
    CHECK_FALSE(first.known);
    CHECK_FALSE(first.still);
    for (int i = 0; i < 5; ++i) {
        const ViewShift next = measure(motion, *image);
        CHECK(next.known);
        CHECK(next.still);
        CHECK(next.shift.x == 0.0);
        CHECK(next.shift.y == 0.0);
        CHECK(next.drift.x == 0.0);
        CHECK(next.drift.y == 0.0);
    }
}

TEST_CASE("A panning view is not still, and its shift is measured to a third of a pixel", "[view]") {
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    const rays::Point steps[] = {{1.5, 0.0}, {0.0, -0.75}, {-2.25, 1.0}, {4.0, 3.5}, {0.6, 0.6}};
    rays::Point pan{10.0, 20.0};
    view(*image, pan);
    measure(motion, *image);
    for (const rays::Point step : steps) {
        pan = {pan.x - step.x, pan.y - step.y};  // the view shifts by `step`: the world by −step under it
        view(*image, pan);
        const ViewShift v = measure(motion, *image);
        INFO("step " << step.x << ", " << step.y << ": measured " << v.shift.x << ", " << v.shift.y);
        CHECK(v.known);
        CHECK_FALSE(v.still);
        CHECK(std::abs(v.shift.x - step.x) <= 0.3);
        CHECK(std::abs(v.shift.y - step.y) <= 0.3);
        CHECK(v.drift.x == v.shift.x);
        CHECK(v.drift.y == v.shift.y);
    }
}

TEST_CASE("A view panning less than a quarter of a pixel a frame counts as still, and drifts as it pans", "[view]") {
    // Each frame's shift is too small to count as the view moving (differencing shows little of it),
    // but over frames it adds up: the drift says how far.
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    const rays::Point steps[] = {{0.2, 0.0}, {0.0, -0.15}, {-0.2, 0.1}, {0.15, 0.15}};
    rays::Point pan{10.0, 20.0};
    view(*image, pan);
    measure(motion, *image);
    for (const rays::Point step : steps) {
        pan = {pan.x - step.x, pan.y - step.y};
        view(*image, pan);
        const ViewShift v = measure(motion, *image);
        INFO("step " << step.x << ", " << step.y << ": drift " << v.drift.x << ", " << v.drift.y);
        CHECK(v.still);
        CHECK(std::abs(v.drift.x - step.x) <= 0.06);
        CHECK(std::abs(v.drift.y - step.y) <= 0.06);
    }
}

TEST_CASE("A crowd crossing the lower half of a still view leaves it still", "[view]") {
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    for (int i = 0; i < 8; ++i) {
        view(*image, {0.0, 0.0});
        // Four walkers of their own looks, each at its own speed, filling the lower half across.
        for (int k = 0; k < 4; ++k) paint_mover(*image, 32.0 * k + (1.0 + 0.4 * k) * i, 64.0 + 4 * k, 26, 60 - 4 * k, 10u + k);
        const ViewShift v = measure(motion, *image);
        if (i == 0) continue;
        INFO("frame " << i << ": measured " << v.shift.x << ", " << v.shift.y << ", drift " << v.drift.x << ", " << v.drift.y);
        CHECK(v.still);
        CHECK(std::abs(v.drift.x) <= 0.1);  // the crowd's bands moved; the still ones hardly
        CHECK(std::abs(v.drift.y) <= 0.1);
    }
}

TEST_CASE("A view panning behind a target the camera follows is not still", "[view]") {
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    for (int i = 0; i < 6; ++i) {
        view(*image, {2.0 * i, 0.0});                          // the view shifts by −2 px a frame
        paint_mover(*image, 50.0, 30.0, 24, 70, 7u);            // the runner stays put in it
        const ViewShift v = measure(motion, *image);
        if (i == 0) continue;
        INFO("frame " << i << ": measured " << v.shift.x << ", " << v.shift.y);
        CHECK(v.known);
        CHECK_FALSE(v.still);
        CHECK(std::abs(v.shift.x + 2.0) <= 0.2);
    }
}

TEST_CASE("A change of light is not motion, and a flat view is still", "[view]") {
    auto image = std::make_unique<FloatImage>();
    ViewMotion motion;
    view(*image, {0.0, 0.0});
    measure(motion, *image);
    view(*image, {0.0, 0.0}, 1.3, 12.0);
    CHECK(measure(motion, *image).still);
    view(*image, {0.0, 0.0}, 0.6, -5.0);
    CHECK(measure(motion, *image).still);

    ViewMotion sky;
    image->px.fill(180.0f);
    measure(sky, *image);
    image->px.fill(190.0f);
    const ViewShift v = measure(sky, *image);
    CHECK(v.known);
    CHECK(v.still);
}

TEST_CASE("The previous frame aligned by the view's shift matches this one where both see the world", "[view]") {
    // A world panned by (3, −2) px between two frames: this frame at x is the previous one at x − shift.
    const rays::Point shift{3.0, -2.0};
    auto previous = std::make_unique<rays::GreyImage>();
    auto frame = std::make_unique<rays::GreyImage>();
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) {
            previous->at(x, y) = static_cast<std::uint8_t>(std::lround(smooth_blocks(x, y, 2u)));
            frame->at(x, y) = static_cast<std::uint8_t>(std::lround(smooth_blocks(x - shift.x, y - shift.y, 2u)));
        }
    auto out = std::make_unique<rays::GreyImage>();
    const rays::GreyImage& aligned = rays::align_previous(*previous, *frame, shift, *out);
    CHECK(&aligned == out.get());
    int worst = 0, unchanged = 0;
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) {
            worst = std::max(worst, std::abs(aligned.at(x, y) - frame->at(x, y)));
            unchanged += aligned.at(x, y) == previous->at(x, y);
        }
    CHECK(worst == 0);  // off the previous frame this frame stands in; elsewhere the world moved along
    CHECK(unchanged < rays::kFramePixels / 4);  // it was moved, not copied
    // The other way, the shift undone, it is the previous frame that is not matched.
    const rays::GreyImage& wrong = rays::align_previous(*previous, *frame, {-3.0, 2.0}, *out);
    int differing = 0;
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x) differing += wrong.at(x, y) != frame->at(x, y);
    CHECK(differing > rays::kFramePixels / 2);
    // No shift: the previous frame itself.
    CHECK(&rays::align_previous(*previous, *frame, {0.0, 0.0}, *out) == previous.get());
}
