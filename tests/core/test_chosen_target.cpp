// SPDX-License-Identifier: Apache-2.0
// A person's chosen target (core/chosen_target.hpp) on a scene drawn here
// (support/textured_filter_scene.hpp): a textured square on a differently textured background, its
// looks learned at the start.
#include <catch2/catch.hpp>

#include <memory>

#include "core/chosen_target.hpp"
#include "core/target_model.hpp"
#include "support/textured_filter_scene.hpp"

namespace {

using rays::ChosenTarget;
using rays::Point;
using rays::test::Images;
using rays::test::TexturedScene;

constexpr double kStartGrey = 0.8;  // the start's inside grey over the frame's mean
constexpr double kSurePsr = 12.0;   // the tracking filter's match this frame

struct Started {
    TexturedScene scene;
    std::unique_ptr<Images> frame = std::make_unique<Images>();
    std::unique_ptr<ChosenTarget> chosen = std::make_unique<ChosenTarget>();
    Point background{100.0, 24.0};  // plain background, well away from the target

    Started() {
        chosen->begin(true);
        chosen->remember_start(kStartGrey, *rays::test::learned_on(scene, *frame));
    }
    bool vouches(Point track, Point motion, double psr = kSurePsr, double grey = kStartGrey) {
        return chosen->vouches_for(frame->smoothed, frame->chroma, track, motion, psr, grey);
    }
};

}  // namespace

TEST_CASE("A person's target is vouched for where its start's looks find it, not where they find it at the motion",
          "[chosen]") {
    Started s;
    // The track holds the target; the motion is on background: the target, standing still or not.
    CHECK(s.vouches(s.scene.target, s.background));
    // The motion is beside the target, within its window: found there too, less clearly.
    CHECK(s.vouches(s.scene.target, {s.scene.target.x + 6.0, s.scene.target.y}));
    // The track holds background while the start's looks are where the motion is: not the target.
    CHECK_FALSE(s.vouches(s.background, s.scene.target));
}

TEST_CASE("A person's target is vouched for only while its track is the person's, the filter sure and the grey as at "
          "the start",
          "[chosen]") {
    Started s;
    const Point target = s.scene.target;
    REQUIRE(s.vouches(target, s.background));
    CHECK_FALSE(s.vouches(target, s.background, rays::CorrelationFilter::kConfidentPsr - 0.5));
    CHECK(s.vouches(target, s.background, rays::CorrelationFilter::kConfidentPsr));
    const double tolerance = rays::TargetModel::kGreyTolerance;
    CHECK(s.vouches(target, s.background, kSurePsr, kStartGrey + 0.9 * tolerance));
    CHECK_FALSE(s.vouches(target, s.background, kSurePsr, kStartGrey + 1.1 * tolerance));
    CHECK_FALSE(s.vouches(target, s.background, kSurePsr, kStartGrey - 1.1 * tolerance));
    s.chosen->begin(false);  // a detector's new track
    CHECK_FALSE(s.vouches(target, s.background));
    s.chosen->begin(true);
    s.chosen->forget_start_grey();  // nothing to compare the grey with
    CHECK_FALSE(s.vouches(target, s.background));
}

TEST_CASE("A detector's track is the person's target again where the start's looks find it", "[chosen]") {
    Started s;
    const ChosenTarget::Standing before = s.chosen->standing_now();
    CHECK(before.standing);
    CHECK(before.start_grey == kStartGrey);
    // A detector's start on background: not the person's target, and it has no start grey.
    s.chosen->begin(false);
    s.chosen->forget_start_grey();
    CHECK_FALSE(s.chosen->found_again(s.frame->smoothed, s.frame->chroma, s.background, before));
    CHECK_FALSE(s.chosen->standing());
    CHECK_FALSE(s.chosen->as_grey_as_at_start(kStartGrey));
    // On the target: the person's again, compared with the grey at its start.
    CHECK(s.chosen->found_again(s.frame->smoothed, s.frame->chroma, s.scene.target, before));
    CHECK(s.chosen->standing());
    CHECK(s.chosen->as_grey_as_at_start(kStartGrey));
    // A failed start gives back what was.
    s.chosen->begin(false);
    s.chosen->forget_start_grey();
    s.chosen->restore(before);
    CHECK(s.chosen->standing());
    CHECK(s.chosen->as_grey_as_at_start(kStartGrey));
}

TEST_CASE("A person's choice holds until reinit, whatever track follows", "[chosen]") {
    ChosenTarget chosen;
    CHECK_FALSE(chosen.chosen());
    chosen.choose();
    chosen.begin(false);  // the detector's track after a loss
    CHECK(chosen.chosen());
    chosen.forget_choice();
    CHECK_FALSE(chosen.chosen());
}
