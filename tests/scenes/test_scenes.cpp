#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "scenes/scene.hpp"

using namespace rays;
using namespace rays::scenes;

TEST_CASE("Scenes are deterministic and every named scene has at least 300 frames", "[scenes]") {
    for (auto name : scene_names()) {
        auto scene = make_scene(name);
        REQUIRE(scene);
        CHECK(scene->frame_count() >= 300);
        SceneFrame a, b, c;
        scene->render(7, a);
        scene->render(7, b);
        scene->render(8, c);
        CHECK(a.image.px == b.image.px);
        CHECK(a.image.px != c.image.px);
        SceneFrame first;
        scene->render(0, first);
        CHECK(scene->init().x == Approx(first.truth.cx));
    }
    CHECK(make_scene("no-such-scene") == nullptr);
}

TEST_CASE("A polygon tracing the disc scores high IoU and a shifted one lower", "[scenes]") {
    auto scene = make_scene("disc");
    SceneFrame f;
    scene->render(0, f);
    CHECK(f.truth.area == Approx(3.14159 * 14 * 14).epsilon(0.03));
    std::vector<Point> circle, shifted;
    for (int i = 0; i < 90; ++i) {
        const double a = 2 * 3.14159265 * i / 90;
        circle.push_back({f.truth.cx + 14 * std::cos(a), f.truth.cy + 14 * std::sin(a)});
        shifted.push_back({f.truth.cx + 6 + 14 * std::cos(a), f.truth.cy + 14 * std::sin(a)});
    }
    CHECK(polygon_mask_iou(circle, f.mask) > 0.95);
    CHECK(polygon_mask_iou(shifted, f.mask) < 0.75);
    CHECK(polygon_mask_iou(std::vector<Point>{{1, 1}, {2, 2}}, f.mask) == 0.0);
}

TEST_CASE("The speed ramp spans 2 to 16 px/frame and the approach grows threefold", "[scenes]") {
    auto ramp = make_scene("speed-ramp");
    SceneFrame a, b;
    double slow = 1e9, fast = 0;
    for (int i = 0; i + 1 < ramp->frame_count(); ++i) {
        ramp->render(i, a);
        ramp->render(i + 1, b);
        const double v = std::abs(b.truth.cx - a.truth.cx);
        if (v > 0.5) slow = std::min(slow, v);
        fast = std::max(fast, v);
    }
    CHECK(slow < 2.5);
    CHECK(fast > 14.0);
    auto approach = make_scene("approach");
    approach->render(0, a);
    approach->render(approach->frame_count() - 1, b);
    CHECK(b.truth.area > 6.0 * a.truth.area);
}
