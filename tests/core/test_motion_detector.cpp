// Motion detection of the initialisation stage (paper §4.1) on frames drawn here from fixed seeds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/motion_detector.hpp"

namespace {

using rays::Detection;
using rays::DetectTunables;
using rays::GreyImage;
using rays::kFrameSize;
using rays::MotionDetector;

constexpr std::uint8_t kBackground = 20;

GreyImage blank(std::uint8_t grey = kBackground) {
    GreyImage image;
    image.px.fill(grey);
    return image;
}

bool inside_disc(int x, int y, int cx, int cy, int r) {
    return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= r * r;
}

// A surface pattern fixed to the object: 2x2 cells of grey 110..255 chosen by a hash of the cell and
// the seed, so moving the disc moves its texture with it (as a pedestrian's clothing moves with them).
std::uint8_t texture(int dx, int dy, unsigned seed) {
    const auto cell_x = static_cast<unsigned>((dx + 1024) / 2);
    const auto cell_y = static_cast<unsigned>((dy + 1024) / 2);
    unsigned h = cell_x * 73856093u ^ cell_y * 19349663u ^ seed * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return static_cast<std::uint8_t>(110u + h % 146u);
}

void draw_textured_disc(GreyImage& image, int cx, int cy, int r, unsigned seed) {
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            if (inside_disc(x, y, cx, cy, r)) image.at(x, y) = texture(x - cx, y - cy, seed);
}

void draw_uniform_disc(GreyImage& image, int cx, int cy, int r, std::uint8_t grey) {
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            if (inside_disc(x, y, cx, cy, r)) image.at(x, y) = grey;
}

void add_noise(GreyImage& image, double sigma, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sigma);
    for (auto& p : image.px) p = static_cast<std::uint8_t>(std::clamp(std::lround(p + noise(rng)), 0L, 255L));
}

void add_brightness(GreyImage& image, int offset) {
    for (auto& p : image.px) p = static_cast<std::uint8_t>(std::clamp(p + offset, 0, 255));
}

double distance(rays::Point p, double x, double y) { return std::hypot(p.x - x, p.y - y); }

}  // namespace

TEST_CASE("A moving textured disc is found between its two positions", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 60, 64, 14, 7);
    draw_textured_disc(current, 64, 64, 14, 7);
    add_noise(previous, 3.0, 1);
    add_noise(current, 3.0, 2);

    const DetectTunables tunables;
    MotionDetector detector;
    detector.reset(tunables);
    const Detection d = detector.detect(previous, current, tunables);

    REQUIRE(d.found);
    CHECK(distance(d.centre, 62.0, 64.0) < 3.0);
    CHECK(d.regions == 1);
    CHECK(d.x0 <= 48);  // the union of both positions: x in [46, 78]
    CHECK(d.x1 >= 76);
    CHECK(d.radius_px == Approx(std::sqrt(d.area_px / 3.141592653589793)));
    CHECK(d.radius_px > 10.0);
    CHECK(d.radius_px < 18.0);
    CHECK(d.threshold == tunables.threshold);
    CHECK(d.passes == 1);
}

TEST_CASE("A moving uniform disc gives two crescents and the chosen one lies on the disc", "[motion_detector]") {
    // Only the leading and trailing edges of an untextured object change; after the opening they are
    // two separate regions of equal size, so the centre lands on one of them, not between positions.
    GreyImage previous = blank(), current = blank();
    draw_uniform_disc(previous, 60, 64, 12, 200);
    draw_uniform_disc(current, 64, 64, 12, 200);
    add_noise(previous, 2.0, 3);
    add_noise(current, 2.0, 4);

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);

    REQUIRE(d.found);
    CHECK(d.regions == 2);
    CHECK(d.area_px < 12 * 12 * 3.14 / 2);
    CHECK(std::abs(d.centre.y - 64.0) < 2.0);
    CHECK(std::min(distance(d.centre, 60, 64), distance(d.centre, 64, 64)) < 12.0);
}

TEST_CASE("Of two moving objects the larger is chosen", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 96, 90, 8, 11);
    draw_textured_disc(current, 96, 94, 8, 11);
    draw_textured_disc(previous, 38, 40, 16, 12);
    draw_textured_disc(current, 42, 40, 16, 12);
    add_noise(previous, 2.0, 5);
    add_noise(current, 2.0, 6);

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);

    REQUIRE(d.found);
    CHECK(d.regions == 2);
    CHECK(distance(d.centre, 40.0, 40.0) < 3.0);
    CHECK(d.x1 < 70);
}

TEST_CASE("Frames without motion give no detection and lower the threshold", "[motion_detector]") {
    const DetectTunables tunables;
    MotionDetector detector;

    SECTION("identical frames") {
        GreyImage frame = blank();
        draw_textured_disc(frame, 64, 64, 20, 3);
        add_noise(frame, 2.0, 7);
        const Detection d = detector.detect(frame, frame, tunables);
        CHECK_FALSE(d.found);
        CHECK(d.regions == 0);
        CHECK(d.passes > 1);
        CHECK(detector.threshold() < tunables.threshold);
        CHECK(detector.threshold() >= tunables.threshold_min);
    }
    SECTION("a static scene with independent mild noise in each frame") {
        GreyImage previous = blank(), current = blank();
        draw_textured_disc(previous, 64, 64, 20, 3);
        draw_textured_disc(current, 64, 64, 20, 3);
        add_noise(previous, 2.0, 8);
        add_noise(current, 2.0, 9);
        for (int frame = 0; frame < 3; ++frame) CHECK_FALSE(detector.detect(previous, current, tunables).found);
        CHECK(detector.threshold() == tunables.threshold_min);
        CHECK(detector.detect(previous, current, tunables).passes == 1);  // pinned at the bound: one pass
    }
}

TEST_CASE("Heavy noise at a low initial threshold raises the threshold and still finds the object",
          "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 60, 64, 18, 21);
    draw_textured_disc(current, 64, 64, 18, 21);
    add_noise(previous, 25.0, 10);
    add_noise(current, 25.0, 11);

    DetectTunables tunables;
    tunables.threshold = 8.0;
    MotionDetector detector;
    detector.reset(tunables);
    const Detection d = detector.detect(previous, current, tunables);

    CHECK(d.passes > 1);
    CHECK(d.threshold > tunables.threshold);
    REQUIRE(d.found);
    CHECK(d.regions <= tunables.max_regions);
    CHECK(distance(d.centre, 62.0, 64.0) < 14.0);  // on the object; at this noise the region may fragment
    CHECK(detector.threshold() == d.threshold);

    // The adapted threshold is kept: the same conditions in the next frame need a single pass.
    const Detection next = detector.detect(previous, current, tunables);
    CHECK(next.found);
    CHECK(next.passes == 1);
    CHECK(next.threshold == d.threshold);

    detector.reset(tunables);
    CHECK(detector.threshold() == tunables.threshold);
}

TEST_CASE("A global brightness change raises the threshold instead of giving one giant region",
          "[motion_detector]") {
    GreyImage previous = blank(60);
    draw_textured_disc(previous, 64, 64, 20, 5);
    GreyImage current = previous;
    add_brightness(current, 50);
    add_noise(previous, 2.0, 12);
    add_noise(current, 2.0, 13);

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);

    CHECK_FALSE(d.found);
    CHECK(d.passes > 1);
    CHECK(detector.threshold() > tunables.threshold);
    CHECK(detector.threshold() <= tunables.threshold_max);
}

TEST_CASE("The opening removes isolated single-pixel changes and thin scratches", "[motion_detector]") {
    DetectTunables tunables;
    tunables.min_area_px = 1;    // so that only the opening can remove them
    tunables.max_regions = 100;  // and not the "too many regions" rule
    GreyImage previous = blank();
    add_noise(previous, 2.0, 14);
    GreyImage current = previous;

    SECTION("30 random single-pixel flips") {
        std::mt19937 rng(15);
        std::uniform_int_distribution<int> coordinate(0, kFrameSize - 1);
        for (int i = 0; i < 30; ++i) current.at(coordinate(rng), coordinate(rng)) = 255;
    }
    SECTION("a two-pixel-wide scratch") {
        for (int x = 20; x < 100; ++x) current.at(x, 50) = current.at(x, 51) = 255;
    }
    MotionDetector detector;
    detector.reset(tunables);
    const Detection d = detector.detect(previous, current, tunables);
    CHECK_FALSE(d.found);
    CHECK(d.regions == 0);
}

TEST_CASE("Regions are 8-connected and measured exactly", "[motion_detector]") {
    // Two 6x6 squares meeting only at a corner: the opening keeps them, the closing does not join them
    // any further, and 8-connectivity makes them one region.
    const GreyImage previous = blank();
    GreyImage current = blank();
    for (int y = 30; y < 36; ++y)
        for (int x = 30; x < 36; ++x) current.at(x, y) = current.at(x + 6, y + 6) = 200;

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);
    REQUIRE(d.found);
    CHECK(d.regions == 1);
    CHECK(d.area_px == 72);
    CHECK(d.centre.x == Approx(35.5));
    CHECK(d.centre.y == Approx(35.5));
    CHECK(d.x0 == 30);
    CHECK(d.y0 == 30);
    CHECK(d.x1 == 41);
    CHECK(d.y1 == 41);
}

TEST_CASE("An object at the frame border is found", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 2, 64, 12, 9);
    draw_textured_disc(current, 6, 64, 12, 9);
    add_noise(previous, 2.0, 16);
    add_noise(current, 2.0, 17);

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);
    REQUIRE(d.found);
    CHECK(d.x0 == 0);
    CHECK(std::abs(d.centre.y - 64.0) < 3.0);
}

TEST_CASE("The threshold stays within its bounds over varied frames", "[motion_detector]") {
    DetectTunables tunables;
    tunables.threshold = 30.0;
    MotionDetector detector;
    detector.reset(tunables);
    std::mt19937 rng(18);
    std::uniform_real_distribution<double> sigma(0.0, 40.0);
    std::uniform_int_distribution<int> brightness(-60, 60);
    std::uniform_int_distribution<int> position(20, 108);
    for (int frame = 0; frame < 40; ++frame) {
        GreyImage previous = blank(), current = blank();
        const int x = position(rng), y = position(rng);
        draw_textured_disc(previous, x, y, 12, 4);
        draw_textured_disc(current, x + 3, y + 2, 12, 4);
        if (frame % 3 == 0) add_brightness(current, brightness(rng));
        add_noise(previous, sigma(rng), 100u + 2u * static_cast<unsigned>(frame));
        add_noise(current, sigma(rng), 101u + 2u * static_cast<unsigned>(frame));
        const Detection d = detector.detect(previous, current, tunables);
        CHECK(d.passes >= 1);
        CHECK(d.passes <= MotionDetector::kMaxPasses);
        CHECK(d.threshold >= tunables.threshold_min);
        CHECK(d.threshold <= tunables.threshold_max);
        CHECK(detector.threshold() >= tunables.threshold_min);
        CHECK(detector.threshold() <= tunables.threshold_max);
    }

    SECTION("an initial threshold outside the bounds is clamped") {
        tunables.threshold = 500.0;
        detector.reset(tunables);
        CHECK(detector.threshold() == tunables.threshold_max);
        tunables.threshold = 1.0;
        detector.reset(tunables);
        CHECK(detector.threshold() == tunables.threshold_min);
    }
    SECTION("narrowed bounds clamp the remembered threshold") {
        detector.reset(tunables);
        tunables.threshold_min = 50.0;
        const Detection d = detector.detect(blank(), blank(), tunables);
        CHECK(d.threshold == 50.0);
        CHECK(detector.threshold() == 50.0);
    }
}

TEST_CASE("Detection is deterministic", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 50, 70, 15, 2);
    draw_textured_disc(current, 54, 67, 15, 2);
    add_noise(previous, 20.0, 19);
    add_noise(current, 20.0, 20);
    DetectTunables tunables;
    tunables.threshold = 7.0;

    MotionDetector first, second;
    first.reset(tunables);
    second.reset(tunables);
    const Detection a = first.detect(previous, current, tunables);
    const Detection b = second.detect(previous, current, tunables);
    first.reset(tunables);
    const Detection c = first.detect(previous, current, tunables);

    for (const Detection* other : {&b, &c}) {
        CHECK(a.found == other->found);
        CHECK(a.centre.x == other->centre.x);
        CHECK(a.centre.y == other->centre.y);
        CHECK(a.area_px == other->area_px);
        CHECK(a.x0 == other->x0);
        CHECK(a.y0 == other->y0);
        CHECK(a.x1 == other->x1);
        CHECK(a.y1 == other->y1);
        CHECK(a.regions == other->regions);
        CHECK(a.threshold == other->threshold);
        CHECK(a.passes == other->passes);
    }
    CHECK(first.threshold() == second.threshold());
}
