// SPDX-License-Identifier: Apache-2.0
// rays-soak's judgement of a run, on hand-made records: the loss rule (the true centre leaves the
// image, or the contour is off it for more than 5 frames), re-acquisition, the centred fraction and
// the fastest speed kept before the first loss.
#include <catch2/catch.hpp>
#include <string>

#include "soak_metrics.hpp"

using namespace rays;
using namespace rays::soak;

namespace {

// n frames at 25 fps, target and contour at the frame's centre, speed rising 1 deg/s per frame.
std::vector<SoakFrame> steady(int n) {
    std::vector<SoakFrame> frames(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k) {
        SoakFrame& f = frames[static_cast<std::size_t>(k)];
        f.t_s = k * 0.04;
        f.target_in_image = true;
        f.truth_px = {63.5, 63.5};
        f.has_contour = true;
        f.contour_px = {64.0, 63.0};
        f.speed_deg_s = k;
        f.latency_us = static_cast<float>(100 + k % 10);
    }
    return frames;
}

}  // namespace

TEST_CASE("a run on target throughout has no loss and is all centred") {
    SoakSummary s = summarise(steady(100));
    CHECK(s.frames == 100);
    CHECK(s.losses.empty());
    CHECK(s.centred_fraction == 1.0);
    CHECK(s.on_target_fraction == 1.0);
    CHECK(s.max_speed_deg_s == 99.0);
    CHECK(s.latency_median_us == Approx(105).margin(1));
}

TEST_CASE("five frames off target are forgiven, six are a loss") {
    for (int off : {5, 6}) {
        std::vector<SoakFrame> frames = steady(100);
        for (int k = 40; k < 40 + off; ++k) frames[static_cast<std::size_t>(k)].contour_px = {63.5 + 13.0, 63.5};
        SoakSummary s = summarise(frames);
        INFO(off << " frames off");
        if (off == 5) {
            CHECK(s.losses.empty());
            CHECK(s.max_speed_deg_s == 99.0);
        } else {
            REQUIRE(s.losses.size() == 1);
            CHECK(s.losses[0].start_s == Approx(40 * 0.04));  // the first frame off target
            CHECK(s.losses[0].reacquire_s == Approx(off * 0.04));
            CHECK(s.losses[0].cause == LossCause::OffTarget);  // a contour, beside the target
            CHECK(s.max_speed_deg_s == 39.0);  // the fastest while on target before the loss
        }
        CHECK(s.on_target_fraction == Approx((100.0 - off) / 100.0));
    }
}

TEST_CASE("the true centre leaving the image is a loss at once, and a lost contour never re-acquired says so") {
    std::vector<SoakFrame> frames = steady(50);
    frames[20].target_in_image = false;
    for (int k = 30; k < 50; ++k) frames[static_cast<std::size_t>(k)].has_contour = false;
    SoakSummary s = summarise(frames);
    REQUIRE(s.losses.size() == 2);
    CHECK(s.losses[0].start_s == Approx(20 * 0.04));
    CHECK(s.losses[0].reacquire_s == Approx(0.04));
    CHECK(s.losses[1].start_s == Approx(30 * 0.04));
    CHECK(s.losses[1].reacquire_s < 0);
    CHECK(s.losses[0].cause == LossCause::LeftImage);
    CHECK(s.losses[1].cause == LossCause::NoContour);
    CHECK(std::string(to_string(s.losses[1].cause)) == "no contour");
    CHECK(s.max_speed_deg_s == 19.0);
}

TEST_CASE("centred counts the true centre within 10 % of the image size of the frame's centre") {
    std::vector<SoakFrame> frames = steady(10);
    for (int k = 0; k < 5; ++k) {
        frames[static_cast<std::size_t>(k)].truth_px = {63.5 + 13.0, 63.5};
        frames[static_cast<std::size_t>(k)].contour_px = {63.5 + 13.0, 63.5};
    }
    SoakSummary s = summarise(frames);
    CHECK(s.centred_fraction == 0.5);
    CHECK(s.on_target_fraction == 1.0);
}

TEST_CASE("frames before the target is first on target are acquisition, not a loss") {
    std::vector<SoakFrame> frames = steady(40);
    for (int k = 0; k < 12; ++k) frames[static_cast<std::size_t>(k)].has_contour = false;
    SoakSummary s = summarise(frames);
    CHECK(s.acquired_s == Approx(12 * 0.04));
    CHECK(s.losses.empty());
    CHECK(s.max_speed_deg_s == 39.0);
}
