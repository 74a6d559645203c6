// SPDX-License-Identifier: Apache-2.0
// The greedy snake of Williams & Shah on drawn frames: it shrinks from a larger circle onto a disc,
// marks the corners of a square, keeps to its settings' limits and stops before its deadline.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <memory>

#include "core/gaussian_smoother.hpp"
#include "snake/greedy_snake.hpp"
#include "snake/snake_contour.hpp"
#include "snake_test_support.hpp"

namespace {

using namespace std::chrono_literals;
using rays::Contour;
using rays::FloatImage;
using rays::Point;
using rays::SnakeTunables;
using rays::TrackerCapacity;
using rays::scenes::Box;
using rays::scenes::Disc;
using rays::scenes::SceneFrame;
using rays::snake::GreedySnake;
using rays::snake::SnakeRun;
using rays::snake_test::iou;
using rays::snake_test::SteppingClock;

// A snake on one smoothed frame, with its contour.
struct Fit {
    TrackerCapacity capacity;
    GreedySnake snake{capacity.max_snake_points};
    Contour contour{rays::snake::snake_contour_capacity(capacity)};
    rays::GaussianSmoother smoother;
    std::unique_ptr<FloatImage> smoothed = std::make_unique<FloatImage>();
    std::unique_ptr<SceneFrame> frame = std::make_unique<SceneFrame>();
    rays::SteadyClock steady;

    Fit() { smoother.set_sigma(snake.tunables().sigma_px); }

    void see() {
        smoother.smooth(frame->image, *smoothed);
        snake.set_image(*smoothed);
    }

    SnakeRun run(const rays::Clock& clock, rays::TimePoint deadline) {
        const SnakeRun r = snake.run(clock, deadline);
        rays::snake::write_snake_contour(snake, *smoothed, r, contour);
        return r;
    }
    SnakeRun run() { return run(steady, rays::TimePoint::max()); }
};

}  // namespace

TEST_CASE("the snake shrinks from a larger circle onto a drawn disc", "[snake]") {
    Fit fit;
    const Disc disc{64, 64, 14};
    rays::snake_test::draw(disc, *fit.frame);
    fit.see();
    // Centred, and off the disc's centre by a few pixels.
    for (const Point start : {Point{64, 64}, Point{67, 62}}) {
        INFO("start circle round " << start.x << ", " << start.y);
        fit.snake.set_circle(start, 1.3 * disc.r);
        const SnakeRun r = fit.run();
        INFO(r.iterations << " passes, IoU " << iou(fit.contour, *fit.frame));
        CHECK(r.converged);
        CHECK_FALSE(r.deadline_hit);
        CHECK(iou(fit.contour, *fit.frame) >= 0.8);
        CHECK(std::hypot(fit.contour.centroid.x - 64, fit.contour.centroid.y - 64) < 1.0);
        CHECK(fit.contour.size == fit.snake.tunables().points);
        CHECK(fit.contour.no_edge_rays == 0);
        CHECK(fit.contour.levels == 1);
        for (int i = 0; i < fit.contour.size; ++i) {
            const rays::ContourPoint& c = fit.contour.points[static_cast<std::size_t>(i)];
            CHECK(c.lambda == Approx(disc.r).margin(1.5));
            CHECK(c.grad < 0);  // bright inside: the grey falls outward
            if (i > 0) CHECK(c.phi > fit.contour.points[static_cast<std::size_t>(i - 1)].phi);
        }
    }
}

TEST_CASE("the snake marks the corners of a square and keeps them sharp", "[snake]") {
    Fit fit;
    const Box square{44, 44, 84, 84};
    rays::snake_test::draw(square, *fit.frame);
    fit.see();
    fit.snake.set_circle({64, 64}, 29);  // round the square, through nothing but background
    const SnakeRun r = fit.run();
    INFO(r.iterations << " passes, IoU " << iou(fit.contour, *fit.frame));
    CHECK(iou(fit.contour, *fit.frame) >= 0.85);
    int corners = 0;
    for (int i = 0; i < fit.snake.size(); ++i) {
        if (!fit.snake.corner(i)) continue;
        ++corners;
        const auto& p = fit.snake.point(i);
        INFO("corner at " << p.x << ", " << p.y);
        CHECK(std::abs(std::abs(p.x - 64) - 20) <= 2);
        CHECK(std::abs(std::abs(p.y - 64) - 20) <= 2);
    }
    CHECK(corners >= 3);
}

TEST_CASE("the snake's settings stay within its capacity", "[snake]") {
    GreedySnake snake(64);
    SnakeTunables t = snake.tunables();
    const SnakeTunables before = t;
    for (auto bad : {+[](SnakeTunables& s) { s.points = 65; }, +[](SnakeTunables& s) { s.points = 4; },
                     +[](SnakeTunables& s) { s.neighbourhood = 4; }, +[](SnakeTunables& s) { s.neighbourhood = 17; },
                     +[](SnakeTunables& s) { s.max_iterations = 0; }, +[](SnakeTunables& s) { s.alpha = -1; },
                     +[](SnakeTunables& s) { s.image_floor = 0; }}) {
        t = before;
        t.gamma = 2.0;
        bad(t);
        CHECK_FALSE(snake.configure(t));
        CHECK(snake.tunables().gamma == before.gamma);
    }
    t = before;
    t.points = 64;
    t.neighbourhood = 7;
    CHECK(snake.configure(t));
    CHECK(snake.tunables().points == 64);
}

TEST_CASE("a new point count resamples the snake along its length", "[snake]") {
    GreedySnake snake(128);
    snake.set_circle({64, 64}, 20);
    SnakeTunables t = snake.tunables();
    t.points = 100;
    REQUIRE(snake.configure(t));
    REQUIRE(snake.size() == 100);
    for (int i = 0; i < snake.size(); ++i) {
        const auto& p = snake.point(i);
        CHECK(std::hypot(p.x - 64, p.y - 64) == Approx(20).margin(1.5));
    }
}

TEST_CASE("the snake stops its passes before the deadline", "[snake]") {
    Fit fit;
    rays::snake_test::draw(Disc{64, 64, 14}, *fit.frame);
    fit.see();
    constexpr auto step = 1us;

    SECTION("a deadline that leaves time for a few passes") {
        SteppingClock clock(step);
        fit.snake.set_circle({64, 64}, 30);  // far from the disc: many passes needed
        const rays::TimePoint deadline = rays::TimePoint{} + 6 * step;
        const SnakeRun r = fit.run(clock, deadline);
        INFO(r.iterations << " passes, " << clock.reads() << " clock reads");
        CHECK(r.deadline_hit);
        CHECK_FALSE(r.converged);
        CHECK(r.iterations >= 1);
        CHECK(r.iterations < fit.snake.tunables().max_iterations);
        CHECK(clock.last_read() <= deadline);
        CHECK(fit.contour.deadline_hit);
        CHECK(fit.contour.levels == 0);
        CHECK(fit.contour.iterations == r.iterations);
        CHECK(fit.contour.size == fit.snake.tunables().points);
    }
    SECTION("a deadline already passed: no pass, the start contour stands") {
        SteppingClock clock(step);
        fit.snake.set_circle({64, 64}, 20);
        const SnakeRun r = fit.run(clock, rays::TimePoint{});
        CHECK(r.deadline_hit);
        CHECK(r.iterations == 0);
        REQUIRE(fit.contour.size == fit.snake.tunables().points);
        for (int i = 0; i < fit.contour.size; ++i)
            CHECK(fit.contour.points[static_cast<std::size_t>(i)].lambda == Approx(20).margin(1.0));
    }
}
