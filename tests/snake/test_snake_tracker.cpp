// SPDX-License-Identifier: Apache-2.0
// GreedySnakeTracker in the loop: detection, tracking a slow disc, losing a target that jumps
// beyond its window, keeping a fast one with predict_next, the per-frame deadline, and box starts.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <memory>

#include "snake/greedy_snake_tracker.hpp"
#include "snake_test_support.hpp"

namespace {

using namespace std::chrono_literals;
using rays::GreedySnakeTracker;
using rays::Point;
using rays::SteadyClock;
using rays::TrackerConfig;
using rays::TrackState;
using rays::scenes::Disc;
using rays::scenes::SceneFrame;
using rays::snake_test::SteppingClock;

constexpr double kRadius = 14;

// A snake tracker with no deadline per frame (one in real time would make the verdict depend on the
// machine's load), and the frame it saw last.
struct Run {
    SteadyClock clock;
    TrackerConfig config;
    std::unique_ptr<GreedySnakeTracker> tracker;
    std::unique_ptr<SceneFrame> frame = std::make_unique<SceneFrame>();

    explicit Run(TrackerConfig c = {}) : config(c), tracker(std::make_unique<GreedySnakeTracker>(config, clock)) {}

    TrackState step(const rays::scenes::Scene& s, int index) {
        s.render(index, *frame);
        return tracker->process(frame->image, rays::TimePoint::max()).state;
    }
    TrackState step_disc(Point centre, int index) {
        rays::snake_test::draw(Disc{centre.x, centre.y, kRadius}, *frame, static_cast<std::uint64_t>(index) + 1);
        return tracker->process(frame->image, rays::TimePoint::max()).state;
    }
    double iou() const { return rays::snake_test::iou(tracker->contour(), *frame); }
};

// x of a disc running back and forth between 30 and 98 at `speed` px/frame, on the row y = 64.
Point running(int t, double speed) {
    const double span = 98 - 30, d = std::fmod(t * speed, 2 * span);
    return {30 + (d < span ? d : 2 * span - d), 64};
}

}  // namespace

TEST_CASE("GreedySnakeTracker detects the moving disc and follows it", "[snake][tracker]") {
    // "disc": radius 14, circling at about 1.5 px/frame.
    const auto s = rays::scenes::make_scene("disc");
    REQUIRE(s != nullptr);
    Run run;
    CHECK(std::string(run.tracker->method()) == "snake");
    int first = -1;
    for (int i = 0; i < 5 && first < 0; ++i)
        if (run.step(*s, i) == TrackState::Tracking) first = i;
    REQUIRE(first >= 1);  // the detector needs a frame pair
    CHECK(run.tracker->result().has_contour);
    CHECK(run.iou() >= 0.8);
    double worst = 1.0;
    for (int i = first + 1; i < first + 120; ++i) {
        INFO("frame " << i);
        REQUIRE(run.step(*s, i) == TrackState::Tracking);
        worst = std::min(worst, run.iou());
        const rays::Contour& c = run.tracker->contour();
        CHECK(c.ref.x == c.centroid.x);
        CHECK(c.size == run.tracker->tunables().snake.points);
    }
    INFO("tracking from frame " << first << ", worst IoU " << worst);
    CHECK(worst >= 0.8);
}

TEST_CASE("GreedySnakeTracker loses a target that jumps beyond its window, then finds it again", "[snake][tracker]") {
    Run run;
    run.tracker->start_at({40, 50});
    int i = 0;
    for (; i < 10; ++i) {
        INFO("frame " << i);
        REQUIRE(run.step_disc({40 + 0.5 * i, 50}, i) == TrackState::Tracking);
    }
    CHECK(run.iou() >= 0.8);
    CHECK(run.step_disc({95, 90}, i++) == TrackState::Lost);  // 60 px away, the window reaches 2 px
    CHECK(run.tracker->result().lost_reason != nullptr);
    CHECK_FALSE(run.tracker->result().has_contour);
    int found_at = -1;
    for (; i < 20 && found_at < 0; ++i)
        if (run.step_disc({95 + 1.5 * (i - 10), 90}, i) == TrackState::Tracking) found_at = i;
    INFO("tracking again at frame " << found_at);
    REQUIRE(found_at > 10);
    CHECK(run.iou() >= 0.8);
}

TEST_CASE("predict_next keeps a target that moves faster than the snake's window", "[snake][tracker]") {
    constexpr double kSpeed = 9;  // px/frame; the 5 × 5 window reaches 2 px per pass
    TrackerConfig config;
    config.tunables.predict = false;  // no guess of its own: the window alone, or predict_next
    for (const bool predicted : {false, true}) {
        INFO((predicted ? "with" : "without") << " predict_next");
        Run run(config);
        run.tracker->start_at(running(0, kSpeed));
        REQUIRE(run.step_disc(running(0, kSpeed), 0) == TrackState::Tracking);
        int tracked = 0;
        double worst = 1.0;
        for (int t = 1; t < 40; ++t) {
            if (predicted) run.tracker->predict_next(running(t, kSpeed));
            if (run.step_disc(running(t, kSpeed), t) != TrackState::Tracking) break;
            ++tracked;
            worst = std::min(worst, run.iou());
        }
        INFO(tracked << " frames tracked, worst IoU " << worst);
        if (predicted) {
            CHECK(tracked == 39);
            CHECK(worst >= 0.8);
            CHECK(run.tracker->result().predicted.x == Approx(running(39, kSpeed).x));
        } else {
            CHECK(tracked < 39);
        }
    }
}

TEST_CASE("GreedySnakeTracker stops the greedy passes before the frame's deadline", "[snake][tracker]") {
    const Point centre{64, 64};
    SteppingClock clock(1us);
    TrackerConfig config;
    GreedySnakeTracker tracker(config, clock);
    const auto frame = std::make_unique<SceneFrame>();
    rays::snake_test::draw(Disc{centre.x, centre.y, kRadius}, *frame);

    tracker.start_at(centre);
    REQUIRE(tracker.process(frame->image, clock.now() + 1h).state == TrackState::Tracking);
    CHECK_FALSE(tracker.contour().deadline_hit);
    CHECK(tracker.contour().levels == 1);

    // The next frame, 6 px off the prediction, with time for two passes: too few to converge.
    rays::snake_test::draw(Disc{centre.x + 6, centre.y, kRadius}, *frame, 2);
    const rays::TimePoint deadline = clock.now() + 3us;
    tracker.process(frame->image, deadline);
    INFO(tracker.contour().iterations << " passes");
    CHECK(tracker.contour().deadline_hit);
    CHECK(tracker.contour().levels == 0);
    CHECK(tracker.contour().iterations >= 1);
    CHECK(tracker.contour().iterations < config.tunables.snake.max_iterations);
    CHECK(clock.last_read() <= deadline);
}

TEST_CASE("GreedySnakeTracker tunables change only within the capacities", "[snake][tracker]") {
    Run run;
    const rays::TrackerTunables before = run.tracker->tunables();
    rays::TrackerTunables too_many = before;
    too_many.snake.points = run.tracker->capacity().max_snake_points + 1;
    too_many.snake.alpha = 0.5;
    CHECK_FALSE(run.tracker->set_tunables(too_many));
    CHECK(run.tracker->tunables().snake.alpha == before.snake.alpha);

    rays::TrackerTunables more = before;
    more.snake.points = 64;
    more.snake.neighbourhood = 7;
    REQUIRE(run.tracker->set_tunables(more));
    run.tracker->start_at({64, 64});
    REQUIRE(run.step_disc({64, 64}, 0) == TrackState::Tracking);
    CHECK(run.tracker->contour().size == 64);
    CHECK(run.iou() >= 0.8);

    more.snake.points = 32;  // while tracking: the snake is resampled, the track kept
    REQUIRE(run.tracker->set_tunables(more));
    REQUIRE(run.step_disc({65, 64}, 1) == TrackState::Tracking);
    CHECK(run.tracker->contour().size == 32);
    CHECK(run.iou() >= 0.8);

    run.tracker->release();
    CHECK(run.tracker->state() == TrackState::Detecting);
    CHECK_FALSE(run.tracker->result().has_contour);
}

TEST_CASE("GreedySnakeTracker started in a box follows the target from the box's ellipse", "[snake][tracker][box]") {
    using rays::scenes::Ellipse;
    const auto target = [](int t) { return Ellipse{40.0 + 0.5 * t, 64.0, 24.0, 10.0}; };
    Run run;
    CHECK_FALSE(run.tracker->start_in({0, 0, 10, 0}));
    REQUIRE(run.tracker->start_in({16, 54, 49, 21}));  // the ellipse's extent in frame 0, as cv::Rect
    for (int t = 0; t < 20; ++t) {
        INFO("frame " << t);
        rays::snake_test::draw(target(t), *run.frame, static_cast<std::uint64_t>(t) + 1);
        REQUIRE(run.tracker->process(run.frame->image, rays::TimePoint::max()).state == TrackState::Tracking);
        CHECK(run.iou() >= 0.85);
    }
}
