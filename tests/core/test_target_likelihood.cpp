// SPDX-License-Identifier: Apache-2.0
// How the target's likelihood map joins the colours and the motion layers, on scenes drawn here: a
// textured target of the world's own texture and colour moving one way while the view pans the
// other. With colour the layers call the whole target the target; on a grey source they may only
// call the scene the scene; on a still view, or without the caller's word on a grey source, they
// are not read at all.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>

#include "core/target_likelihood.hpp"
#include "core/view_motion.hpp"
#include "support/block_texture.hpp"
#include "support/map_means.hpp"

namespace {

using rays::Point;

constexpr double kRadius = 14.0;  // the target's, px
constexpr Point kStart{50.0, 64.0};

// The scene over `frames` frames: the target moves by `step` a frame, the view by `view`; the map
// is then looked at with the target `tracking`.
struct Scene {
    std::unique_ptr<rays::FloatImage> image = std::make_unique<rays::FloatImage>();
    std::unique_ptr<rays::GreyImage> grey = std::make_unique<rays::GreyImage>();
    rays::Chroma chroma;  // one colour everywhere: the colours cannot tell the target
    rays::Contour contour{rays::TrackerCapacity{}};
    rays::ViewMotion view_motion;
    rays::TargetLikelihood likelihood;
    Point target = kStart;

    explicit Scene(bool colour) {
        chroma.u.fill(128);
        chroma.v.fill(128);
        chroma.present = colour;
    }

    void draw(Point pan) {
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                const double dx = x - target.x, dy = y - target.y;
                const bool on = dx * dx + dy * dy <= kRadius * kRadius;
                const double v = on ? rays::test::smooth_blocks(dx, dy, 7u, 4.0, 40, 160)
                                    : rays::test::smooth_blocks(x + pan.x, y + pan.y, 1u, 5.0, 40, 160);
                image->at(x, y) = static_cast<float>(v);
                grey->at(x, y) = static_cast<std::uint8_t>(std::lround(v));
            }
    }

    // A contour round part of the target: a circle of 0.35 of its radius about its centre.
    void round_part() {
        contour.size = 64;
        contour.ref = target;
        for (int i = 0; i < contour.size; ++i) {
            const double a = 2.0 * std::numbers::pi * i / contour.size;
            contour.points[static_cast<std::size_t>(i)].p = {target.x + 0.35 * kRadius * std::cos(a),
                                                            target.y + 0.35 * kRadius * std::sin(a)};
        }
        rays::polygon_area_centroid(contour.points.data(), contour.size, contour.area, contour.centroid);
    }

    // Frames 0 … frames as the tracker runs them; `expected`: the caller's word on the view's shift.
    void run(int frames, Point step, Point view, bool expected) {
        for (int f = 0; f <= frames; ++f) {
            target = {kStart.x + f * step.x, kStart.y + f * step.y};
            draw({-f * view.x, -f * view.y});
            likelihood.begin_frame(*grey, chroma, expected ? std::optional<Point>(view) : std::nullopt);
            view_motion.take(*image);
            round_part();
            if (f == 0) likelihood.seed(target, 0.3 * kRadius, 2.0 * kRadius, 3.0 * kRadius);
            else likelihood.learn_motion(*image, contour, step, view_motion);
            likelihood.keep_frame(*image);
        }
    }
};

constexpr Point kStep{1.0, 0.0};
constexpr Point kPan{-1.5, 0.5};

}  // namespace

TEST_CASE("TargetLikelihood: with colour, the layers call the whole target the target while the view pans", "[target_likelihood]") {
    Scene s(true);
    s.likelihood.configure(true, true);
    s.run(6, kStep, kPan, false);
    REQUIRE(s.likelihood.colours().valid());
    REQUIRE(s.likelihood.layers_on());
    const rays::LikelihoodMap* map = s.likelihood.look(true, {0.0, 0.0});
    REQUIRE(map != nullptr);
    CHECK(map->split_rims);
    const rays::test::MapMeans m = rays::test::map_means(*map, s.target);
    INFO("target " << m.target << ", background " << m.background);
    CHECK(m.target > 1.0);
    CHECK(m.background < -1.0);
    // Not while the track is lost: where the target was is no guide to where it is found again.
    const rays::test::MapMeans lost = rays::test::map_means(*s.likelihood.look(false, {0.0, 0.0}), s.target);
    CHECK(lost.target < 0.5 * m.target);
}

TEST_CASE("TargetLikelihood: on a grey source the layers say only where the scene is, and only on the caller's word", "[target_likelihood]") {
    Scene s(false);
    s.likelihood.configure(true, true);
    s.run(6, kStep, kPan, true);
    CHECK_FALSE(s.likelihood.colours().valid());
    REQUIRE(s.likelihood.layers_on());
    const rays::LikelihoodMap* map = s.likelihood.look(true, {0.0, 0.0});
    REQUIRE(map != nullptr);
    CHECK_FALSE(map->split_rims);
    const rays::test::MapMeans m = rays::test::map_means(*map, s.target);
    INFO("target " << m.target << ", background " << m.background << ", most " << m.most);
    CHECK(m.background < -1.0);
    CHECK(m.most <= 0.0f);  // never the target: other movers going its way would be taken for it

    // Without the caller's word on how the unit turned, a grey source keeps no layers.
    Scene unsaid(false);
    unsaid.likelihood.configure(true, true);
    unsaid.run(6, kStep, kPan, false);
    CHECK_FALSE(unsaid.likelihood.layers_on());
    CHECK(unsaid.likelihood.look(true, {0.0, 0.0}) == nullptr);
}

TEST_CASE("TargetLikelihood: on a still view the layers are not read, and with the term off nothing is", "[target_likelihood]") {
    Scene still(false);
    still.likelihood.configure(true, true);
    still.run(6, kStep, {0.0, 0.0}, true);
    CHECK(still.likelihood.look(true, {0.0, 0.0}) == nullptr);

    Scene off(true);
    off.likelihood.configure(false, true);
    off.run(6, kStep, kPan, false);
    CHECK_FALSE(off.likelihood.colours().valid());
    CHECK_FALSE(off.likelihood.layers_on());
    CHECK(off.likelihood.look(true, {0.0, 0.0}) == nullptr);
}
