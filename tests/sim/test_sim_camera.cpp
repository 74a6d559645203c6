// SPDX-License-Identifier: Apache-2.0
// The simulated camera's views: determinism, geometry against the camera model, visibility and
// occlusion, exposure, and the truth's speeds.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numeric>

#include "core/gaussian_smoother.hpp"
#include "core/view_motion.hpp"
#include "sim_rig.hpp"
#include "support/emulator.hpp"

using namespace rays;
using namespace rays::sim;
using rays::test::camera_on;
using rays::test::named_camera;
using rays::test::separation_deg;
using rays::test::still_disc;

namespace {

constexpr double kCentre = (kFrameSize - 1) / 2.0;

double mean_grey(const GreyImage& image) {
    return std::accumulate(image.px.begin(), image.px.end(), 0.0) / kFramePixels;
}

int mask_pixels(const GreyImage& mask) {
    return static_cast<int>(std::count(mask.px.begin(), mask.px.end(), std::uint8_t{255}));
}

// The view with the unit pointed straight at the primary target at time t.
void render_on_target(const SimCamera& camera, double t, SimView& view) {
    const PathPoint at = camera.scenario().targets[camera.scenario().primary].path->at(t);
    camera.render(t, at.position.azimuth, at.position.elevation, view);
}

}  // namespace

TEST_CASE("the same time and angles give the same view, another time other noise") {
    const auto camera = named_camera("patrol");
    REQUIRE(camera);
    auto a = std::make_unique<SimView>(), b = std::make_unique<SimView>(), c = std::make_unique<SimView>();
    camera->render(3.25, 0.1, -0.05, *a);
    camera->render(3.25, 0.1, -0.05, *b);
    camera->render(3.25 + 1e-9, 0.1, -0.05, *c);
    CHECK(a->image.px == b->image.px);
    CHECK(a->mask.px == b->mask.px);
    CHECK(a->truth.visible_px == b->truth.visible_px);
    CHECK(a->image.px != c->image.px);
    CHECK(a->mask.px == c->mask.px);
}

TEST_CASE("with the unit pointed at the target its mask is centred in the frame") {
    SECTION("the ramp's disc, wherever it swings") {
        const auto camera = named_camera("ramp");
        auto view = std::make_unique<SimView>();
        for (double t : {0.0, 7.3, 31.0, 64.2, 119.0}) {
            render_on_target(*camera, t, *view);
            INFO("t = " << t);
            REQUIRE(view->truth.in_view);
            CHECK(view->truth.centre_px.x == Approx(kCentre).margin(1e-9));
            CHECK(view->truth.centre_px.y == Approx(kCentre).margin(1e-9));
            CHECK(view->truth.mask_centroid_px.x == Approx(kCentre).margin(1.0));
            CHECK(view->truth.mask_centroid_px.y == Approx(kCentre).margin(1.0));
            CHECK(view->truth.visible_fraction == Approx(1.0));
        }
    }
    SECTION("a still disc high up, low down and across ±180°, where azimuth and elevation bend most") {
        for (auto [az, el] : {std::pair{0.0, 0.0}, {30.0, 45.0}, {-75.0, -50.0}, {180.0, 20.0}, {-179.0, 0.0}}) {
            const SimCamera camera = camera_on(still_disc(az, el));
            auto view = std::make_unique<SimView>();
            camera.render(1.0, az * kRadPerDeg, el * kRadPerDeg, *view);
            INFO("at " << az << ", " << el);
            REQUIRE(view->truth.in_view);
            CHECK(view->truth.mask_centroid_px.x == Approx(kCentre).margin(0.5));
            CHECK(view->truth.mask_centroid_px.y == Approx(kCentre).margin(0.5));
            // A disc 10° across seen face-on: π·(5°·fx)² pixels.
            const double radius_px = std::tan(5.0 * kRadPerDeg) * camera.camera().intrinsics().fx;
            CHECK(view->truth.visible_px == Approx(std::numbers::pi * radius_px * radius_px).epsilon(0.02));
            CHECK(mask_pixels(view->mask) == Approx(view->truth.visible_px).epsilon(0.03));
        }
    }
}

TEST_CASE("panning the unit right by θ moves the target left by fx·tan θ, tilting up moves it down") {
    const SimCamera camera = camera_on(still_disc(20, 0));
    const double fx = camera.camera().intrinsics().fx, fy = camera.camera().intrinsics().fy;
    auto view = std::make_unique<SimView>();
    for (double theta : {1.0, 4.0, 12.0, -7.0}) {
        INFO("θ = " << theta);
        camera.render(0.0, (20 + theta) * kRadPerDeg, 0.0, *view);
        REQUIRE(view->truth.in_view);
        const double shift = fx * std::tan(theta * kRadPerDeg);
        CHECK(view->truth.centre_px.x == Approx(kCentre - shift).margin(1e-9));
        // Off the axis perspective stretches the disc outward, moving its centroid a little further.
        CHECK(view->truth.mask_centroid_px.x == Approx(kCentre - shift).margin(0.2 + 0.02 * std::abs(shift)));
        CHECK(view->truth.mask_centroid_px.y == Approx(kCentre).margin(0.2));
    }
    camera.render(0.0, 20 * kRadPerDeg, 6 * kRadPerDeg, *view);
    CHECK(view->truth.centre_px.y == Approx(kCentre + fy * std::tan(6 * kRadPerDeg)).margin(1e-9));
    CHECK(view->truth.mask_centroid_px.y == Approx(view->truth.centre_px.y).margin(0.3));
}

TEST_CASE("turning the unit moves the whole view by CameraModel::view_shift, as the view's bands measure it") {
    // The world only (the walker far off): what ViewMotion measures between two views rendered at
    // the same time (the same noise) is the turn's shift alone.
    const auto camera = named_camera("patrol");
    REQUIRE(camera);
    auto a = std::make_unique<SimView>(), b = std::make_unique<SimView>();
    const double pan0 = 2.5, tilt0 = -0.05;
    for (const auto& [dpan_deg, dtilt_deg] : {std::pair{0.5, 0.0}, {-1.0, 0.4}, {1.5, -0.8}, {0.0, 1.2}}) {
        INFO("turned by " << dpan_deg << "°, " << dtilt_deg << "°");
        const double pan1 = pan0 + dpan_deg * kRadPerDeg, tilt1 = tilt0 + dtilt_deg * kRadPerDeg;
        camera->render(3.0, pan0, tilt0, *a);
        camera->render(3.0, pan1, tilt1, *b);
        REQUIRE_FALSE(a->truth.in_view);
        const std::optional<Point> told = camera->camera().view_shift(pan0, tilt0, pan1, tilt1);
        REQUIRE(told);
        // Panning right brings the world in from the right: it moves left; about fx·tan θ.
        CHECK(told->x == Approx(-camera->camera().intrinsics().fx * std::tan(dpan_deg * kRadPerDeg)).margin(0.1));
        auto smooth = std::make_unique<FloatImage>();
        GaussianSmoother smoother;
        smoother.set_sigma(1.0);
        ViewMotion motion;
        smoother.smooth(a->image, *smooth);
        motion.take(*smooth);
        smoother.smooth(b->image, *smooth);
        motion.take(*smooth);
        const ViewShift& measured = motion.since_previous();
        INFO("told " << told->x << ", " << told->y << "; measured " << measured.shift.x << ", " << measured.shift.y);
        REQUIRE(measured.known);
        CHECK(measured.shift.x == Approx(told->x).margin(0.3));
        CHECK(measured.shift.y == Approx(told->y).margin(0.3));
    }
}

TEST_CASE("a target behind the camera or outside the field of view is not in view and has no mask") {
    const SimCamera camera = camera_on(still_disc(10, 0));
    auto view = std::make_unique<SimView>();
    SECTION("behind") {
        camera.render(0.0, (10 + 180) * kRadPerDeg, 0.0, *view);
        CHECK_FALSE(view->truth.in_view);
        CHECK(mask_pixels(view->mask) == 0);
        CHECK(view->truth.visible_px == 0.0);
        CHECK(view->truth.visible_fraction == 0.0);
        CHECK(std::isnan(view->truth.centre_px.x));
        CHECK(std::isnan(view->truth.mask_centroid_px.x));
        CHECK(std::isnan(view->truth.speed_px_per_s));
    }
    SECTION("beside: 40° to the left of the axis, past the 30° half field and the disc's 5° radius") {
        camera.render(0.0, (10 + 40) * kRadPerDeg, 0.0, *view);
        CHECK_FALSE(view->truth.in_view);
        CHECK(mask_pixels(view->mask) == 0);
        CHECK(view->truth.visible_px == 0.0);
        CHECK(view->truth.centre_px.x < -0.5);
        CHECK(view->truth.centre_px.y == Approx(kCentre));
        CHECK(std::isnan(view->truth.mask_centroid_px.x));
    }
    SECTION("half out at the frame's edge: in view, but only about half its area") {
        camera.render(0.0, (10 + 30) * kRadPerDeg, 0.0, *view);
        CHECK(view->truth.in_view);
        CHECK(view->truth.visible_fraction == Approx(1.0));  // nothing in front of it, only cut off
        CHECK(view->truth.centre_px.x == Approx(-0.5).margin(1e-6));
        CHECK(view->truth.mask_centroid_px.x < 6.0);
    }
}

TEST_CASE("occluders and targets in front reduce the visible fraction") {
    const double fx = test::demo_camera().intrinsics().fx;
    SECTION("a pole 2° wide down the middle of a disc 10° across") {
        Scenario s = still_disc(0, 0);
        s.occluders.push_back({-1 * kRadPerDeg, 1 * kRadPerDeg, -60 * kRadPerDeg, 60 * kRadPerDeg, 200});
        const SimCamera camera = camera_on(std::move(s));
        auto view = std::make_unique<SimView>();
        camera.render(0.0, 0.0, 0.0, *view);
        // A strip of half-width w through a disc of radius r hides (2/π)(asin(w/r) + (w/r)√(1 − w²/r²)).
        const double w = 1.0 / 5.0, hidden = 2 / std::numbers::pi * (std::asin(w) + w * std::sqrt(1 - w * w));
        CHECK(view->truth.in_view);
        CHECK(view->truth.visible_fraction == Approx(1 - hidden).margin(0.02));
        CHECK(view->mask.at(64, 64) == 0);                        // behind the pole
        CHECK(view->image.at(64, 64) == 200);                      // the pole's grey
        CHECK(view->mask.at(static_cast<int>(kCentre + 3 * kRadPerDeg * fx), 64) == 255);
        CHECK(view->truth.mask_centroid_px.x == Approx(kCentre).margin(0.5));
    }
    SECTION("a second target passing in front") {
        Scenario s = still_disc(0, 0);
        s.targets.push_back({DiscShape{6}, 220, 0, 1, test::standing_at(5, 0), {}});
        const SimCamera camera = camera_on(std::move(s));
        auto view = std::make_unique<SimView>();
        camera.render(0.0, 0.0, 0.0, *view);
        CHECK(view->truth.visible_fraction < 0.95);
        CHECK(view->truth.visible_fraction > 0.7);
        CHECK(view->truth.mask_centroid_px.x < kCentre - 0.5);  // its right side is hidden
    }
}

TEST_CASE("an occluder shows wherever it is in view, at any tilt, up to the frame's corners") {
    // A pole 3° wide from the ground to +70°, with the disc behind the camera; no noise.
    Scenario s = still_disc(180, 0);
    s.occluders.push_back({40 * kRadPerDeg, 43 * kRadPerDeg, -89 * kRadPerDeg, 70 * kRadPerDeg, 250});
    const SimCamera camera = camera_on(std::move(s));
    const control::CameraModel& model = camera.camera();
    auto view = std::make_unique<SimView>();
    int checked = 0;
    for (double tilt : {-60.0, -20.0, 0.0, 35.0, 55.0})
        for (double pan = -20.0; pan <= 100.0; pan += 5.0) {
            camera.render(0.0, pan * kRadPerDeg, tilt * kRadPerDeg, *view);
            for (int y = 0; y < kFrameSize; y += 3)
                for (int x = 0; x < kFrameSize; x += 3) {
                    const control::WorldAngles a = model.world_angles({double(x), double(y)}, pan * kRadPerDeg, tilt * kRadPerDeg);
                    // Well inside, by more than a pixel's 0.5°: azimuth shrinks by cos(elevation) on the sphere.
                    const double az = a.azimuth * kDegPerRad, el = a.elevation * kDegPerRad;
                    const double from_sides = std::min(az - 40.0, 43.0 - az) * std::cos(a.elevation);
                    if (from_sides < 0.7 || el < -88.3 || el > 69.3) continue;
                    INFO("pan " << pan << ", tilt " << tilt << ", pixel " << x << ", " << y);
                    CHECK(view->image.at(x, y) == 250);
                    ++checked;
                }
        }
    CHECK(checked > 1000);
}

TEST_CASE("a change of exposure scales the mean grey") {
    Scenario s = still_disc(0, 0);
    s.exposure = {0.0, 60.0, 0.5, 20.0};  // half the gain during the second half of every 20 s
    const SimCamera camera = camera_on(std::move(s));
    auto bright = std::make_unique<SimView>(), dark = std::make_unique<SimView>();
    camera.render(5.0, 0.0, 0.0, *bright);
    camera.render(15.0, 0.0, 0.0, *dark);
    CHECK(mean_grey(dark->image) == Approx(0.5 * mean_grey(bright->image)).epsilon(0.01));
    CHECK(dark->mask.px == bright->mask.px);
}

TEST_CASE("the truth's speeds are the finite differences of its target angles and centre pixel") {
    constexpr double h = 1e-4;
    for (std::string_view name : sim::scenario_names()) {
        const auto camera = named_camera(name);
        auto before = std::make_unique<SimView>(), at = std::make_unique<SimView>(), after = std::make_unique<SimView>();
        for (double t : {0.7, 13.0, 61.5, 127.25}) {
            const double pan = camera->scenario().initial_pan_rad + 0.05, tilt = camera->scenario().initial_tilt_rad;
            camera->render(t - h, pan, tilt, *before);
            camera->render(t, pan, tilt, *at);
            camera->render(t + h, pan, tilt, *after);
            INFO(name << " at t = " << t);
            CHECK(at->truth.speed_deg_s ==
                  Approx(separation_deg(before->truth.target, after->truth.target) / (2 * h)).margin(0.01).epsilon(1e-3));
            if (std::isnan(at->truth.centre_px.x)) continue;
            const double dx = after->truth.centre_px.x - before->truth.centre_px.x;
            const double dy = after->truth.centre_px.y - before->truth.centre_px.y;
            CHECK(at->truth.speed_px_per_s == Approx(std::hypot(dx, dy) / (2 * h)).margin(0.02).epsilon(1e-3));
        }
    }
}

TEST_CASE("the patrol walker's legs swing as it walks") {
    const auto camera = named_camera("patrol");
    auto view = std::make_unique<SimView>();
    int smallest = kFramePixels, largest = 0;
    for (double t = 2.0; t < 5.0; t += 0.1) {  // cruising right at 12 deg/s
        render_on_target(*camera, t, *view);
        REQUIRE(view->truth.in_view);
        smallest = std::min(smallest, mask_pixels(view->mask));
        largest = std::max(largest, mask_pixels(view->mask));
    }
    CHECK(largest > smallest * 1.04);
}

TEST_CASE("render time", "[timing]") {
    rays::test::skip_under_emulation("a timing report, and emulated time says nothing of an arm64 board");
    for (std::string_view name : sim::scenario_names()) {
        const auto camera = named_camera(name);
        auto view = std::make_unique<SimView>();
        constexpr int kFrames = 200;
        const auto start = std::chrono::steady_clock::now();
        for (int i = 0; i < kFrames; ++i) render_on_target(*camera, i * 0.04, *view);
        const std::chrono::duration<double, std::milli> took = std::chrono::steady_clock::now() - start;
        std::printf("render %-7.*s %.3f ms per frame\n", static_cast<int>(name.size()), name.data(), took.count() / kFrames);
    }
}
