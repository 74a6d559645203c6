// SPDX-License-Identifier: Apache-2.0
// Motion detection of the initialisation stage (paper §4.1) on frames drawn here from fixed seeds.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
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

// A step change: the square [x, x + side) × [y, y + side) set to `grey`. Smoothing the difference by the
// 3×3 binomial spreads a step of height h by exactly one pixel (h/4 beside a side, h/16 at a corner), so
// at a threshold below h/16 every square becomes its own bounding square grown by one pixel.
void draw_square(GreyImage& image, int x, int y, int side, std::uint8_t grey) {
    for (int v = y; v < y + side; ++v)
        for (int u = x; u < x + side; ++u) image.at(u, v) = grey;
}

double distance(rays::Point p, double x, double y) { return std::hypot(p.x - x, p.y - y); }

// Adds noise σ to both frames (seeds `seed` and `seed` + 1) and detects with a fresh detector at
// the default tunables.
Detection detect_with_noise(GreyImage& previous, GreyImage& current, double sigma, unsigned seed) {
    add_noise(previous, sigma, seed);
    add_noise(current, sigma, seed + 1);
    const DetectTunables tunables;
    MotionDetector detector;
    return detector.detect(previous, current, tunables);
}

// σ of the 3×3-binomial-smoothed difference of two frames with independent pixel noise σ each:
// the difference has σ·√2, the filter keeps a fraction Σw² ^½ = 0.375 of it.
double smoothed_noise_sigma(double sigma) { return sigma * std::sqrt(2.0) * 0.375; }

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
    CHECK(d.radius_px == Approx(0.5 * std::sqrt((d.x1 - d.x0 + 1) * (d.y1 - d.y0 + 1))));
    CHECK(d.radius_px > 12.0);
    CHECK(d.radius_px < 18.0);
    // Mild noise: the threshold starts at 4 noise σ, below the configured one, and one pass suffices.
    CHECK(d.threshold < tunables.threshold);
    CHECK(d.threshold >= tunables.threshold_min);
    CHECK(d.passes == 1);
}

TEST_CASE("A uniform disc moving by one pixel is found: its thin crescents survive the opening",
          "[motion_detector]") {
    // Each crescent is at most one pixel wide, which a bare 3×3 opening would erase; the smoothed
    // difference widens it to three pixels.
    GreyImage previous = blank(), current = blank();
    draw_uniform_disc(previous, 60, 64, 12, 200);
    draw_uniform_disc(current, 61, 64, 12, 200);
    const Detection d = detect_with_noise(previous, current, 2.0, 22);

    REQUIRE(d.found);
    CHECK(distance(d.centre, 60.5, 64.0) < 2.0);
    CHECK(d.x0 <= 49);  // the outline of both positions: x in [48, 73], y in [52, 76]
    CHECK(d.x1 >= 72);
    CHECK(d.y0 <= 53);
    CHECK(d.y1 >= 75);
    CHECK(d.area_px < 12 * 12 * 3.14);  // an outline, not the filled disc
}

TEST_CASE("The two crescents of a moving uniform disc are merged into one object", "[motion_detector]") {
    // Only the leading and trailing edges of an untextured object change, and after the opening they
    // are two separate regions; they lie within the merge gap of each other, so the centre is the
    // disc's, between its two positions, not on one crescent.
    GreyImage previous = blank(), current = blank();
    draw_uniform_disc(previous, 60, 64, 12, 200);
    draw_uniform_disc(current, 62, 64, 12, 200);
    const Detection d = detect_with_noise(previous, current, 2.0, 3);

    REQUIRE(d.found);
    CHECK(d.regions == 2);
    CHECK(distance(d.centre, 61.0, 64.0) < 3.0);
    CHECK(d.area_px < 12 * 12 * 3.14 / 2);  // the largest region is one crescent only
    CHECK(d.x0 <= 49);                        // the box spans both crescents: x in [48, 74]
    CHECK(d.x1 >= 73);
    CHECK(d.radius_px > 10.0);
}

TEST_CASE("The two edge strips of a wide uniform object are one object beyond the merge gap", "[motion_detector]") {
    // An upright uniform bar (a walker's body, 17 px wide) moving right by 2 px: only its leading and
    // trailing edges change, two long strips 15 px apart, further than the merge gap. They face each
    // other along their whole length, so they are the two sides of one object and m starts between
    // them, on the bar, not on the background beside it.
    GreyImage previous = blank(), current = blank();
    for (int y = 30; y < 90; ++y)
        for (int x = 0; x < 17; ++x) {
            previous.at(50 + x, y) = 200;
            current.at(52 + x, y) = 200;
        }
    const Detection d = detect_with_noise(previous, current, 2.0, 7);

    REQUIRE(d.found);
    CHECK(d.regions == 2);
    CHECK(distance(d.centre, 59.5, 59.5) < 2.0);  // the bar's middle between its two positions
    CHECK(d.x0 <= 51);
    CHECK(d.x1 >= 68);

    SECTION("a strip beside a square is no pair: only the strip's own region") {
        GreyImage square_current = current;
        for (int y = 0; y < 60; ++y)  // the trailing strip stays; a square appears 10 px left of it
            for (int x = 0; x < 60; ++x)
                if (x >= 26 && x < 38 && y >= 50 && y < 62) square_current.at(x, y) = 200;
        for (int y = 30; y < 90; ++y)  // no leading strip: the bar grows no further right
            for (int x = 67; x < 69; ++x) square_current.at(x, y) = previous.at(x, y);
        MotionDetector other;
        const Detection e = other.detect(previous, square_current, DetectTunables{});
        REQUIRE(e.found);
        CHECK(e.regions == 2);
        CHECK(e.x0 >= 45);  // the square (x < 38) not merged
    }
}

namespace {

// Two textured movers far apart: a small disc at (96, 90 → 94) and one twice its radius at (38 → 42, 40).
void draw_two_movers(GreyImage& previous, GreyImage& current) {
    draw_textured_disc(previous, 96, 90, 8, 11);
    draw_textured_disc(current, 96, 94, 8, 11);
    draw_textured_disc(previous, 38, 40, 16, 12);
    draw_textured_disc(current, 42, 40, 16, 12);
}

}  // namespace

TEST_CASE("Of two distant moving objects the larger is chosen", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_two_movers(previous, current);
    const Detection d = detect_with_noise(previous, current, 2.0, 5);

    REQUIRE(d.found);
    CHECK(d.regions == 2);
    CHECK(distance(d.centre, 40.0, 40.0) < 3.0);
    CHECK(d.x1 < 70);  // the small object is far away and not merged
    CHECK(d.y1 < 70);
}

TEST_CASE("Every region found is asked about, the smaller mover the detection left out too", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_two_movers(previous, current);
    add_noise(previous, 2.0, 5);
    add_noise(current, 2.0, 6);
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, DetectTunables{});
    REQUIRE(d.found);
    REQUIRE(distance(d.centre, 40.0, 40.0) < 3.0);  // the larger mover is the detection
    auto near = [](double x, double y) { return [x, y](rays::Point p) { return distance(p, x, y) < 4.0; }; };
    CHECK(detector.any_region(near(96.0, 92.0)));  // the smaller one, left out of it, is asked about too
    CHECK(detector.any_region(near(40.0, 40.0)));
    CHECK_FALSE(detector.any_region(near(96.0, 40.0)));  // where nothing moved
    // Frames without motion: nothing found, no region to ask about.
    const GreyImage still = blank();
    REQUIRE_FALSE(detector.detect(still, still, DetectTunables{}).found);
    CHECK_FALSE(detector.any_region([](rays::Point) { return true; }));
}

TEST_CASE("Regions within 6 px of the growing box of the largest are merged and measured exactly",
          "[motion_detector]") {
    // Step changes of 180 grey levels; with no noise the threshold falls to threshold_min = 6 < 180/16,
    // so each square below is measured as its square grown by one pixel (see draw_square).
    // A: 10×10 drawn at (20, 20): grown x, y in [19, 30], 144 px, centroid (24.5, 24.5) — the largest.
    // B: 6×6 to the right of A, 64 px grown. C: 6×6 up and right of B, found before B in raster order,
    // within 6 px of B but not of A: it joins only once B has grown the box. D: far away.
    const GreyImage previous = blank();
    GreyImage current = blank();
    draw_square(current, 20, 20, 10, 200);
    draw_square(current, 90, 90, 6, 200);  // D
    const DetectTunables tunables;
    MotionDetector detector;

    SECTION("B's grown box starts 6 px after A's: A, B and then C are merged") {
        draw_square(current, 37, 22, 6, 200);  // B grown: x in [36, 43], y in [21, 28]
        draw_square(current, 50, 14, 6, 200);  // C grown: x in [49, 56], y in [13, 20]
        const Detection d = detector.detect(previous, current, tunables);
        REQUIRE(d.found);
        CHECK(d.threshold == tunables.threshold_min);
        CHECK(d.regions == 4);
        CHECK(d.area_px == 144);  // the largest region's own area
        CHECK(d.centre.x == Approx((144 * 24.5 + 64 * 39.5 + 64 * 52.5) / 272.0));
        CHECK(d.centre.y == Approx((144 * 24.5 + 64 * 24.5 + 64 * 16.5) / 272.0));
        CHECK(d.x0 == 19);
        CHECK(d.y0 == 13);
        CHECK(d.x1 == 56);
        CHECK(d.y1 == 30);
        CHECK(d.radius_px == Approx(0.5 * std::sqrt(38.0 * 18.0)));
    }
    SECTION("B's grown box starts 7 px after A's: A stays alone, and so does C") {
        draw_square(current, 38, 22, 6, 200);  // B grown: x in [37, 44]
        draw_square(current, 51, 14, 6, 200);  // C grown: x in [50, 57], still 6 px after B
        const Detection d = detector.detect(previous, current, tunables);
        REQUIRE(d.found);
        CHECK(d.regions == 4);
        CHECK(d.area_px == 144);
        CHECK(d.centre.x == Approx(24.5));
        CHECK(d.centre.y == Approx(24.5));
        CHECK(d.x0 == 19);
        CHECK(d.y0 == 19);
        CHECK(d.x1 == 30);
        CHECK(d.y1 == 30);
        CHECK(d.radius_px == Approx(6.0));
    }
}

TEST_CASE("Frames without motion give no detection and lower the threshold", "[motion_detector]") {
    const DetectTunables tunables;
    MotionDetector detector;

    SECTION("identical frames: no noise, so the threshold drops to its lower bound at once") {
        GreyImage frame = blank();
        draw_textured_disc(frame, 64, 64, 20, 3);
        add_noise(frame, 2.0, 7);
        const Detection d = detector.detect(frame, frame, tunables);
        CHECK_FALSE(d.found);
        CHECK(d.regions == 0);
        CHECK(d.passes == 1);  // started at threshold_min, where lowering cannot go further
        CHECK(d.threshold == tunables.threshold_min);
        CHECK(detector.threshold() == tunables.threshold_min);
    }
    SECTION("a static scene with independent noise in each frame") {
        GreyImage previous = blank(), current = blank();
        draw_textured_disc(previous, 64, 64, 20, 3);
        draw_textured_disc(current, 64, 64, 20, 3);
        add_noise(previous, 4.0, 8);
        add_noise(current, 4.0, 9);
        const Detection first = detector.detect(previous, current, tunables);
        CHECK_FALSE(first.found);
        CHECK(first.regions == 0);
        CHECK(first.passes > 1);  // started at 4 noise σ, above the bound, then lowered
        CHECK(detector.threshold() == tunables.threshold_min);
        const Detection again = detector.detect(previous, current, tunables);
        CHECK_FALSE(again.found);
        CHECK(again.passes == 1);  // pinned at the bound: one pass
    }
}

TEST_CASE("The threshold starts at 4 noise sigma when that is below the remembered one", "[motion_detector]") {
    DetectTunables tunables;
    tunables.threshold = 100.0;
    MotionDetector detector;
    detector.reset(tunables);
    REQUIRE(detector.threshold() == 100.0);

    const double sigma = 8.0;
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 60, 64, 14, 7);
    draw_textured_disc(current, 64, 64, 14, 7);
    add_noise(previous, sigma, 31);
    add_noise(current, sigma, 32);
    const Detection d = detector.detect(previous, current, tunables);

    REQUIRE(d.found);
    CHECK(d.passes == 1);  // a threshold of 100 would have missed most of the object and needed lowering
    const double expected = 4.0 * smoothed_noise_sigma(sigma);  // ≈ 17
    CHECK(d.threshold > 0.75 * expected);
    CHECK(d.threshold < 1.3 * expected);
    CHECK(distance(d.centre, 62.0, 64.0) < 3.0);
    CHECK(detector.threshold() == d.threshold);
}

TEST_CASE("Heavy noise at a low initial threshold raises the threshold and still finds the object",
          "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 60, 64, 18, 21);
    draw_textured_disc(current, 64, 64, 18, 21);
    add_noise(previous, 25.0, 10);
    add_noise(current, 25.0, 11);

    DetectTunables tunables;
    tunables.threshold = 8.0;  // far below 4 noise σ ≈ 53, so the remembered value is where passes start
    MotionDetector detector;
    detector.reset(tunables);
    const Detection d = detector.detect(previous, current, tunables);

    CHECK(d.passes > 1);
    CHECK(d.threshold > tunables.threshold);
    REQUIRE(d.found);
    CHECK(d.regions <= tunables.max_regions);
    CHECK(distance(d.centre, 62.0, 64.0) < 6.0);
    CHECK(detector.threshold() == d.threshold);

    // The adapted threshold is kept: the same conditions in the next frame need a single pass.
    const Detection next = detector.detect(previous, current, tunables);
    CHECK(next.found);
    CHECK(next.passes == 1);
    CHECK(next.threshold == d.threshold);

    // When the noise calms down the threshold follows it down at once, to 4 σ of the quiet pair.
    GreyImage quiet_previous = blank(), quiet_current = blank();
    draw_textured_disc(quiet_previous, 60, 64, 18, 21);
    draw_textured_disc(quiet_current, 64, 64, 18, 21);
    add_noise(quiet_previous, 2.0, 40);
    add_noise(quiet_current, 2.0, 41);
    const Detection quiet = detector.detect(quiet_previous, quiet_current, tunables);
    REQUIRE(quiet.found);
    CHECK(quiet.passes == 1);
    CHECK(quiet.threshold < d.threshold);
    CHECK(quiet.threshold <= std::max(tunables.threshold_min, 4.0 * 1.3 * smoothed_noise_sigma(2.0)));
    CHECK(distance(quiet.centre, 62.0, 64.0) < 3.0);

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

TEST_CASE("Isolated single-pixel changes are not found", "[motion_detector]") {
    DetectTunables tunables;
    GreyImage previous = blank();
    add_noise(previous, 2.0, 14);
    std::mt19937 rng(15);
    std::uniform_int_distribution<int> coordinate(3, kFrameSize - 4);
    // 30 flips at least 7 px apart and 3 px inside the frame, so neither the 3x3 smoothing nor the
    // closing (whose element is clipped at the frame border) joins or grows their spots.
    std::array<std::array<int, 2>, 30> flips{};
    for (auto& flip : flips) {
        bool apart = false;
        while (!apart) {
            flip = {coordinate(rng), coordinate(rng)};
            apart = std::none_of(flips.data(), &flip, [&](const std::array<int, 2>& other) {
                return std::abs(other[0] - flip[0]) < 7 && std::abs(other[1] - flip[1]) < 7;
            });
        }
    }
    GreyImage current = previous;
    MotionDetector detector;

    SECTION("moderate flips: their smoothed spots are plus-shaped and the opening removes them") {
        tunables.min_area_px = 1;    // so that only the opening can remove them
        tunables.max_regions = 100;  // and not the "too many regions" rule
        for (const auto& flip : flips) {
            std::uint8_t& grey = current.at(flip[0], flip[1]);
            grey = static_cast<std::uint8_t>(grey + 60);
        }
        const Detection d = detector.detect(previous, current, tunables);
        CHECK_FALSE(d.found);
        CHECK(d.regions == 0);
    }
    SECTION("saturated flips: 3x3 spots that pass the opening but are smaller than min_area_px") {
        for (const auto& flip : flips) current.at(flip[0], flip[1]) = 255;
        const Detection d = detector.detect(previous, current, tunables);
        CHECK_FALSE(d.found);
        CHECK(d.regions == 0);
        tunables.min_area_px = 1;
        tunables.max_regions = 100;
        const Detection spots = detector.detect(previous, current, tunables);
        CHECK(spots.regions == 30);
        CHECK(spots.area_px == 9);
    }
}

TEST_CASE("Regions are 8-connected and measured exactly", "[motion_detector]") {
    // Two 6x6 step squares meeting only at a corner, at (30, 30) and (36, 36). Each is measured grown by
    // one pixel (see draw_square): 8x8 squares over [29, 36] and [35, 42] sharing a 2x2 corner, one
    // 8-connected region of 64 + 64 - 4 px; the closing fills no notch of that shape.
    const GreyImage previous = blank();
    GreyImage current = blank();
    draw_square(current, 30, 30, 6, 200);
    draw_square(current, 36, 36, 6, 200);

    const DetectTunables tunables;
    MotionDetector detector;
    const Detection d = detector.detect(previous, current, tunables);
    REQUIRE(d.found);
    CHECK(d.threshold == tunables.threshold_min);
    CHECK(d.regions == 1);
    CHECK(d.area_px == 124);
    CHECK(d.centre.x == Approx(35.5));
    CHECK(d.centre.y == Approx(35.5));
    CHECK(d.x0 == 29);
    CHECK(d.y0 == 29);
    CHECK(d.x1 == 42);
    CHECK(d.y1 == 42);
    CHECK(d.radius_px == Approx(7.0));
}

TEST_CASE("An object at the frame border is found", "[motion_detector]") {
    GreyImage previous = blank(), current = blank();
    draw_textured_disc(previous, 2, 64, 12, 9);
    draw_textured_disc(current, 6, 64, 12, 9);
    const Detection d = detect_with_noise(previous, current, 2.0, 16);
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
