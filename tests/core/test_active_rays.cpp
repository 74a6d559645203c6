// SPDX-License-Identifier: Apache-2.0
// Contour extraction with active rays (§2.2–2.4), its any-time refinement and deadline (§2.3), and
// the terms beyond the paper (polarity, region, temporal), on frames drawn here with rays_scenes.
#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/active_rays.hpp"
#include "core/gaussian_smoother.hpp"
#include "scenes/render.hpp"

namespace {

using namespace std::chrono_literals;
using rays::ActiveRays;
using rays::Clock;
using rays::Contour;
using rays::FloatImage;
using rays::Point;
using rays::PolarPrior;
using rays::RaysTunables;
using rays::TargetModel;
using rays::TimePoint;
using rays::TrackerCapacity;
using rays::scenes::Canvas;
using rays::scenes::Ellipse;
using rays::scenes::Random;
using rays::scenes::SceneFrame;
using rays::scenes::Star;

constexpr double kCx = 64, kCy = 64;

// A clock that advances by a fixed step each time it is read, so the extraction's own reads of the
// clock are what spends the time budget.
class SteppingClock final : public Clock {
public:
    explicit SteppingClock(std::chrono::nanoseconds step) : step_(step) {}
    TimePoint now() const override { return t_ += step_; }
    TimePoint start() const { return TimePoint{}; }
    // The time of the last read: one more read minus one step.
    TimePoint last_read() const { return now() - step_; }

private:
    std::chrono::nanoseconds step_;
    mutable TimePoint t_{};
};

// Everything one extraction needs, sized once.
struct Extraction {
    TrackerCapacity capacity;
    RaysTunables tunables;
    ActiveRays rays{capacity};
    PolarPrior prior{capacity.max_rays};
    Contour contour{capacity};
    rays::GaussianSmoother smoother;
    FloatImage smoothed;
    rays::SteadyClock steady;

    Extraction() { REQUIRE(rays.configure(tunables)); }

    void set(const RaysTunables& t) {
        tunables = t;
        REQUIRE(rays.configure(t));
    }

    // Extracts round m from a circle prior of radius 10 (the tracker's first guess), no temporal term.
    const Contour& run(const SceneFrame& frame, Point m, const TargetModel& model = {}, const Clock* clock = nullptr,
                       TimePoint deadline = TimePoint::max(), int max_level = -1, bool m_moves = true) {
        prior.set_circle(10.0);
        return run_with_prior(frame, m, false, model, clock, deadline, max_level, m_moves);
    }

    const Contour& run_with_prior(const SceneFrame& frame, Point m, bool use_temporal, const TargetModel& model = {},
                                  const Clock* clock = nullptr, TimePoint deadline = TimePoint::max(),
                                  int max_level = -1, bool m_moves = true) {
        smoother.set_sigma(tunables.sigma_px);
        smoother.smooth(frame.image, smoothed);
        const Clock& c = clock ? *clock : steady;
        rays.extract(smoothed, m, prior, use_temporal, model, c, deadline, contour, max_level, m_moves);
        return contour;
    }
};

std::vector<Point> points_of(const Contour& c) {
    std::vector<Point> p(static_cast<std::size_t>(c.size));
    for (int i = 0; i < c.size; ++i) p[static_cast<std::size_t>(i)] = c.points[static_cast<std::size_t>(i)].p;
    return p;
}

double iou(const Contour& c, const SceneFrame& frame) {
    const std::vector<Point> p = points_of(c);
    return rays::scenes::polygon_mask_iou(p, frame.mask);
}

double centroid_error(const Contour& c, const SceneFrame& frame) {
    return std::hypot(c.centroid.x - frame.truth.cx, c.centroid.y - frame.truth.cy);
}

// Background, then optional clutter drawn by `extra` (not part of the target), then the target.
template <class Shape, class Extra>
std::unique_ptr<SceneFrame> draw(const Shape& target, double background, double target_grey, double noise,
                                 std::uint64_t seed, Extra extra) {
    auto canvas = std::make_unique<Canvas>();
    canvas->fill(background);
    extra(*canvas);
    canvas->paint(target, target_grey, true);
    Random random(seed);
    canvas->noise(noise, random);
    auto frame = std::make_unique<SceneFrame>();
    canvas->finish(*frame);
    return frame;
}

template <class Shape>
std::unique_ptr<SceneFrame> draw(const Shape& target, double background, double target_grey, double noise,
                                 std::uint64_t seed) {
    return draw(target, background, target_grey, noise, seed, [](Canvas&) {});
}

// The test disc: r = 15 at (64, 64), 80 grey levels above its background, noise σ = 4.
std::unique_ptr<SceneFrame> test_disc() { return draw(Ellipse{kCx, kCy, 15, 15}, 60, 140, 4, 11); }

}  // namespace

TEST_CASE("ActiveRays extracts a disc as a star-shaped contour round m", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    const Contour& c = x.run(*frame, {kCx, kCy});
    INFO("IoU " << iou(c, *frame) << ", centroid error " << centroid_error(c, *frame));
    CHECK(iou(c, *frame) >= 0.9);
    CHECK(centroid_error(c, *frame) < 1.0);
    CHECK(c.size == 360);
    CHECK(c.levels == x.rays.table().levels());
    CHECK_FALSE(c.deadline_hit);
    CHECK(c.area == Approx(frame->truth.area).epsilon(0.08));
    for (int i = 0; i < c.size; ++i) {
        const rays::ContourPoint& p = c.points[static_cast<std::size_t>(i)];
        INFO("point " << i);
        if (i > 0) REQUIRE(p.phi > c.points[static_cast<std::size_t>(i - 1)].phi);  // ordered by angle: no crossings
        REQUIRE(std::hypot(p.p.x - c.ref.x, p.p.y - c.ref.y) == Approx(p.lambda).margin(1e-3));  // eq. 8
        REQUIRE(p.p.x - c.ref.x == Approx(p.lambda * std::cos(p.phi)).margin(1e-3));  // along the ray's angle
        REQUIRE(p.p.y - c.ref.y == Approx(p.lambda * std::sin(p.phi)).margin(1e-3));
        REQUIRE(p.lambda == Approx(15.0).margin(1.5));
    }
}

TEST_CASE("ActiveRays moves m to the centroid from an off-centre start", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    for (const Point m : {Point{kCx + 5, kCy}, Point{kCx, kCy - 5}, Point{kCx - 3.5, kCy + 3.5}}) {
        const Contour& c = x.run(*frame, m);
        INFO("start (" << m.x << ", " << m.y << "): IoU " << iou(c, *frame) << ", centroid error "
                       << centroid_error(c, *frame) << ", iterations " << c.iterations);
        CHECK(c.iterations >= 2);  // eq. 11: m was moved at least once
        CHECK(centroid_error(c, *frame) < 1.0);
        CHECK(std::hypot(c.ref.x - frame->truth.cx, c.ref.y - frame->truth.cy) < 1.0);
        CHECK(iou(c, *frame) >= 0.9);
    }
}

TEST_CASE("ActiveRays holds m where it is told to: the contour seen from an off-centre point", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    const Point m{kCx + 7, kCy - 3};
    const Contour& c = x.run(*frame, m, {}, nullptr, TimePoint::max(), -1, false);
    INFO("IoU " << iou(c, *frame) << ", centroid error " << centroid_error(c, *frame));
    CHECK(c.iterations == 1);
    CHECK(c.ref.x == m.x);  // not moved toward the disc's centre (eq. 11 not applied)
    CHECK(c.ref.y == m.y);
    CHECK(rays::contour_contains(c, m));
    CHECK(centroid_error(c, *frame) < 1.0);  // the same disc, seen from elsewhere inside it
    CHECK(iou(c, *frame) >= 0.9);
}

namespace {

// True when both target and background pixels lie within 2 px of the point λ along the ray from ref.
bool near_mask_boundary(const SceneFrame& frame, Point ref, double phi, double lambda) {
    const double px = ref.x + lambda * std::cos(phi), py = ref.y + lambda * std::sin(phi);
    bool inside = false, outside = false;
    for (int y = static_cast<int>(py) - 2; y <= static_cast<int>(py) + 3; ++y)
        for (int x = static_cast<int>(px) - 2; x <= static_cast<int>(px) + 3; ++x) {
            if (x < 0 || y < 0 || x >= rays::kFrameSize || y >= rays::kFrameSize) continue;
            if (std::hypot(x - px, y - py) > 2.0) continue;
            (frame.mask.at(x, y) > 127 ? inside : outside) = true;
        }
    return inside && outside;
}

}  // namespace

TEST_CASE("ActiveRays extracts a concave star and reports further crossings in its notches", "[active_rays]") {
    auto frame = draw(Star{kCx, kCy, 24, 12, 5, 0.0}, 60, 140, 4, 12);
    Extraction x;
    SECTION("from the centre every ray meets the rim once") {
        const Contour& c = x.run(*frame, {kCx, kCy});
        INFO("IoU " << iou(c, *frame));
        CHECK(iou(c, *frame) >= 0.8);
        CHECK(centroid_error(c, *frame) < 1.0);
        int crossings = 0;
        for (int i = 0; i < c.size; ++i) crossings += c.crossing_count[static_cast<std::size_t>(i)];
        CHECK(crossings == 0);
    }
    SECTION("from a point 6 px off-centre, rays through the notches meet the rim three times") {
        RaysTunables t;
        t.centroid_iterations = 1;  // keep m where it is
        x.set(t);
        const Contour& c = x.run(*frame, {kCx + 6, kCy});
        int rays_with_crossings = 0;
        for (int i = 0; i < c.size; ++i) {
            const rays::ContourPoint& p = c.points[static_cast<std::size_t>(i)];
            for (int k = 0; k < c.crossing_count[static_cast<std::size_t>(i)]; ++k) {
                INFO("ray at " << p.phi << " rad, crossing at λ = " << c.crossing(i, k));
                CHECK(near_mask_boundary(*frame, c.ref, p.phi, c.crossing(i, k)));
            }
            rays_with_crossings += c.crossing_count[static_cast<std::size_t>(i)] > 0;
        }
        INFO("IoU " << iou(c, *frame) << ", rays with further crossings " << rays_with_crossings);
        CHECK(iou(c, *frame) >= 0.8);
        CHECK(rays_with_crossings >= 10);
    }
}

TEST_CASE("ActiveRays works with a ray count that is not a power of two", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    RaysTunables t;
    t.count = 100;
    x.set(t);
    const Contour& c = x.run(*frame, {kCx + 2, kCy - 1});
    INFO("IoU " << iou(c, *frame));
    CHECK(c.size == 100);
    CHECK(c.levels == x.rays.table().levels());
    CHECK(iou(c, *frame) >= 0.9);
    CHECK(centroid_error(c, *frame) < 1.0);
}

TEST_CASE("ActiveRays refuses tunables beyond its capacities", "[active_rays]") {
    TrackerCapacity capacity;
    ActiveRays rays(capacity);
    RaysTunables t;
    t.count = capacity.max_rays + 1;
    CHECK_FALSE(rays.configure(t));
    t.count = 1;
    CHECK_FALSE(rays.configure(t));
    t = {};
    t.hypotheses = capacity.max_hypotheses + 1;
    CHECK_FALSE(rays.configure(t));
    t = {};
    t.lambda_max_px = 2.0 + capacity.max_samples * t.step_px;  // one sample too many
    CHECK_FALSE(rays.configure(t));
    CHECK(rays.table().count() == RaysTunables{}.count);  // unchanged by the refused settings
    t = {};
    t.count = 180;
    CHECK(rays.configure(t));
    CHECK(rays.table().count() == 180);
}

TEST_CASE("ActiveRays any-time: every level refines the contour and never worsens it", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    const rays::RayTable& table = x.rays.table();
    int centroid_level = 0;
    while (table.level_end(centroid_level) < x.tunables.centroid_rays) ++centroid_level;
    double previous = -1;
    for (int level = centroid_level; level < table.levels(); ++level) {
        SteppingClock clock(1us);
        const Contour& c = x.run(*frame, {kCx, kCy}, {}, &clock, clock.start() + 1h, level);
        const double q = iou(c, *frame);
        INFO("max_level " << level << ": " << c.size << " rays, IoU " << q);
        CHECK(c.size == table.level_end(level));
        CHECK(c.levels == level + 1);
        CHECK(q >= 0.9);
        if (previous >= 0) CHECK(q >= previous - 0.02);
        previous = q;
    }
    const Contour& full = x.run(*frame, {kCx, kCy});
    CHECK(full.size == 360);
    CHECK(full.levels == table.levels());
    CHECK(iou(full, *frame) == Approx(previous).margin(1e-9));
}

TEST_CASE("ActiveRays stops refining before the deadline and still returns a contour", "[active_rays]") {
    auto frame = test_disc();
    Extraction x;
    constexpr auto step = 2us;  // every read of the clock costs 2 µs
    const int coarse = x.rays.table().level_end(4);
    REQUIRE(coarse == x.tunables.centroid_rays);

    SECTION("a deadline that leaves time for part of the refinement") {
        SteppingClock clock(step);
        const TimePoint deadline = clock.start() + 20us;
        const Contour& c = x.run(*frame, {kCx, kCy}, {}, &clock, deadline);
        const double late_us = std::chrono::duration<double, std::micro>(clock.last_read() - deadline).count();
        INFO(c.size << " rays, IoU " << iou(c, *frame) << ", last clock read " << late_us << " µs after the deadline");
        CHECK(c.deadline_hit);
        CHECK(c.size < 360);
        CHECK(c.size > coarse);
        CHECK(c.levels < x.rays.table().levels());
        CHECK(iou(c, *frame) >= 0.8);
        CHECK(clock.last_read() <= deadline + 2 * step);
    }
    SECTION("a deadline already passed: the coarse contour only") {
        SteppingClock clock(step);
        const Contour& c = x.run(*frame, {kCx + 3, kCy}, {}, &clock, clock.start());
        INFO("IoU " << iou(c, *frame));
        CHECK(c.deadline_hit);
        CHECK(c.size == coarse);
        CHECK(c.iterations == 1);
        CHECK(iou(c, *frame) >= 0.8);
    }
    SECTION("a deadline far away") {
        SteppingClock clock(step);
        const Contour& c = x.run(*frame, {kCx, kCy}, {}, &clock, clock.start() + 1s);
        CHECK_FALSE(c.deadline_hit);
        CHECK(c.size == 360);
        CHECK(c.levels == x.rays.table().levels());
    }
}

// The terms beyond the paper. Each scene puts a distractor edge beside a disc of 30 grey levels
// contrast that the plain edge energy prefers; the term under test must recover the disc.
namespace {

constexpr double kBackground = 100, kDisc = 130;
const Ellipse kTarget{kCx, kCy, 15, 15};

std::unique_ptr<SceneFrame> clean_disc() { return draw(kTarget, kBackground, kDisc, 3, 21); }

// Learns the target model from an extraction on the clean frame, as the tracker does after a frame.
TargetModel learn_on(Extraction& x, const SceneFrame& clean) {
    TargetModel model;
    std::vector<float> scratch(static_cast<std::size_t>(x.capacity.max_rays));
    const Contour& c = x.run(clean, {kCx, kCy});
    REQUIRE(iou(c, clean) >= 0.9);
    model.learn(c, scratch);
    REQUIRE(model.valid);
    return model;
}

RaysTunables only(double polarity, double region, double temporal) {
    RaysTunables t;
    t.polarity_weight = polarity;
    t.region_weight = region;
    t.temporal_weight = temporal;
    t.jump_cost = 0.0;  // each term alone, under eq. 9's untruncated smoothness
    return t;
}

}  // namespace

TEST_CASE("Polarity term: an edge of the wrong sign beside the target is rejected", "[active_rays][terms]") {
    // A bright slab (200) 4 px right of the bright disc: its edge rises where the disc's rim falls.
    auto frame = draw(kTarget, kBackground, kDisc, 3, 22, [](Canvas& c) { c.rect(83, 30, 127, 98, 200); });
    Extraction x;
    const TargetModel model = learn_on(x, *clean_disc());
    const double plain = iou(x.run(*frame, {kCx, kCy}), *frame);
    x.set(only(0.0, 0.0, 0.0));
    const double without = iou(x.run(*frame, {kCx, kCy}, model), *frame);
    x.set(only(RaysTunables{}.polarity_weight, 0.0, 0.0));
    const double with = iou(x.run(*frame, {kCx, kCy}, model), *frame);
    INFO("IoU plain " << plain << ", model without polarity " << without << ", with polarity " << with);
    CHECK(with >= 0.95);
    CHECK(with >= without + 0.04);
    CHECK(with >= plain + 0.04);
}

TEST_CASE("Region term: an edge of the same sign beside the target is rejected", "[active_rays][terms]") {
    // A dark ring (30) from r = 19 to 24 round the disc: its inner edge falls like the disc's rim.
    auto frame = draw(kTarget, kBackground, kDisc, 3, 23, [](Canvas& c) {
        c.paint(Ellipse{kCx, kCy, 24, 24}, 30, false);
        c.paint(Ellipse{kCx, kCy, 19, 19}, kBackground, false);
    });
    Extraction x;
    const TargetModel model = learn_on(x, *clean_disc());
    const double plain = iou(x.run(*frame, {kCx, kCy}), *frame);
    x.set(only(0.0, 0.0, 0.0));
    const double without = iou(x.run(*frame, {kCx, kCy}, model), *frame);
    x.set(only(0.0, RaysTunables{}.region_weight, 0.0));
    const double with = iou(x.run(*frame, {kCx, kCy}, model), *frame);
    INFO("IoU plain " << plain << ", model without region " << without << ", with region " << with);
    CHECK(with >= 0.95);
    CHECK(with >= without + 0.2);
    CHECK(with >= plain + 0.2);
}

TEST_CASE("Temporal term: the previous contour holds the target against a distractor", "[active_rays][terms]") {
    // A bright slab (220) 8 px right of the disc; the prior is the contour found on the clean frame.
    auto frame = draw(kTarget, kBackground, kDisc, 3, 24, [](Canvas& c) { c.rect(87, 30, 127, 98, 220); });
    auto clean = clean_disc();
    Extraction x;
    const Contour& first = x.run(*clean, {kCx, kCy});
    REQUIRE(iou(first, *clean) >= 0.9);
    const std::vector<Point> previous = points_of(first);
    x.set(only(0.0, 0.0, RaysTunables{}.temporal_weight));
    x.prior.set_polygon(previous.data(), static_cast<int>(previous.size()));
    const double without = iou(x.run_with_prior(*frame, {kCx, kCy}, false), *frame);
    x.prior.set_polygon(previous.data(), static_cast<int>(previous.size()));
    const double with = iou(x.run_with_prior(*frame, {kCx, kCy}, true), *frame);
    INFO("IoU without temporal term " << without << ", with " << with);
    CHECK(with >= 0.95);
    CHECK(with >= without + 0.05);
}

TEST_CASE("ActiveRays: the contour again without jumps is the one an extraction without them finds", "[active_rays]") {
    // The tracker's second look when a tracking contour fails its check: the ring DP again, eq. 9
    // whole, on the rays and hypotheses already found. A bright slab beside the target gives the
    // truncated smoothness something to jump to.
    auto frame = draw(kTarget, kBackground, kDisc, 3, 24, [](Canvas& c) { c.rect(87, 30, 127, 98, 220); });
    auto clean = clean_disc();
    Extraction x;
    const std::vector<Point> previous = points_of(x.run(*clean, {kCx, kCy}));
    CHECK_FALSE(x.rays.solve_without_jumps(x.prior, x.contour));  // a first contour has no jumps

    RaysTunables smooth = x.tunables;
    smooth.jump_cost = 0.0;
    Extraction whole;
    whole.set(smooth);
    whole.prior.set_polygon(previous.data(), static_cast<int>(previous.size()));
    const std::vector<Point> expected = points_of(whole.run_with_prior(*frame, {kCx, kCy}, true));

    x.prior.set_polygon(previous.data(), static_cast<int>(previous.size()));
    const std::vector<Point> jumped = points_of(x.run_with_prior(*frame, {kCx, kCy}, true));
    REQUIRE(x.rays.solve_without_jumps(x.prior, x.contour));
    const std::vector<Point> again = points_of(x.contour);
    REQUIRE(again.size() == expected.size());
    double differs = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < again.size(); ++i) {
        differs = std::max(differs, std::hypot(jumped[i].x - again[i].x, jumped[i].y - again[i].y));
        worst = std::max(worst, std::hypot(expected[i].x - again[i].x, expected[i].y - again[i].y));
    }
    INFO("largest move by leaving the jumps out " << differs << " px");
    CHECK(differs > 1.0);   // the jumps made a difference here ...
    CHECK(worst < 1e-6);    // ... and the second solve undoes it exactly
    CHECK_FALSE(x.rays.solve_without_jumps(x.prior, x.contour));  // once
}

TEST_CASE("Region term: m on a thin bright bar across the target's middle still finds the rim", "[active_rays][terms]") {
    // A pole (220, 3 px wide) in front of the disc's middle, and m on it, as when the target passes
    // behind a pole: every ray starts on the pole. The region term judges the inside by the part of
    // the ray nearer the rim, so those first bright samples do not make every edge look wrong.
    auto canvas = std::make_unique<Canvas>();
    canvas->fill(kBackground);
    canvas->paint(kTarget, kDisc, true);
    canvas->rect(63, 0, 65, 127, 220);
    Random random(25);
    canvas->noise(3, random);
    auto frame = std::make_unique<SceneFrame>();
    canvas->finish(*frame);
    Extraction x;
    const TargetModel model = learn_on(x, *clean_disc());
    const Contour& c = x.run(*frame, {kCx, kCy}, model);
    const double none = static_cast<double>(c.no_edge_rays) / c.size;
    INFO("rays without an edge " << none << ", IoU " << iou(c, *frame));
    CHECK(none <= 0.3);
    CHECK(iou(c, *frame) >= 0.85);
}
