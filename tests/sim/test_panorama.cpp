// SPDX-License-Identifier: Apache-2.0
// The world panorama: generated from a seed, or loaded from a PNG; bilinear lookup by world angles.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "support/temp_dir.hpp"
#include "common/angles.hpp"
#include "io/png_writer.hpp"
#include "sim/panorama.hpp"

using namespace rays;
using sim::Panorama;

namespace {
constexpr double kPi = std::numbers::pi;
}

TEST_CASE("a generated panorama covers the circle at the asked resolution and depends only on its seed") {
    const Panorama a = Panorama::generate(1), again = Panorama::generate(1), other = Panorama::generate(2);
    CHECK(a.width() == 1440);
    CHECK(a.height() == 480);
    CHECK(a.px_per_rad() == Approx(4.0 * 180.0 / kPi));
    int differing = 0;
    for (double az = -179.0; az < 180.0; az += 7.3)
        for (double el = -55.0; el < 56.0; el += 6.1) {
            const double g = a.grey(az * kRadPerDeg, el * kRadPerDeg);
            CHECK(g >= 0.0);
            CHECK(g <= 255.0);
            CHECK(g == again.grey(az * kRadPerDeg, el * kRadPerDeg));
            if (std::abs(g - other.grey(az * kRadPerDeg, el * kRadPerDeg)) > 1.0) ++differing;
        }
    CHECK(differing > 100);
}

TEST_CASE("the panorama is seamless at ±180° and holds its edge rows beyond its band") {
    const Panorama p = Panorama::generate(3);
    for (double el = -50.0; el < 50.0; el += 5.0) {
        CHECK(p.grey(kPi, el * kRadPerDeg) == Approx(p.grey(-kPi, el * kRadPerDeg)).margin(1e-9));
        CHECK(p.grey(kPi + 0.1, el * kRadPerDeg) == Approx(p.grey(-kPi + 0.1, el * kRadPerDeg)).margin(1e-9));
    }
    CHECK(p.grey(0.3, 80 * kRadPerDeg) == p.grey(0.3, 89 * kRadPerDeg));
    CHECK(p.grey(0.3, -80 * kRadPerDeg) == p.grey(0.3, -89 * kRadPerDeg));
}

TEST_CASE("the sky is brighter than the ground on average") {
    const Panorama p = Panorama::generate(4);
    double sky = 0, ground = 0;
    for (double az = -180.0; az < 180.0; az += 1.0) {
        sky += p.grey(az * kRadPerDeg, 30 * kRadPerDeg);
        ground += p.grey(az * kRadPerDeg, -30 * kRadPerDeg);
    }
    CHECK(sky > ground + 360 * 20.0);
}

TEST_CASE("a PNG panorama spans the circle across its width, at the same angle per row, centred on the horizon") {
    constexpr int kWidth = 360, kHeight = 120;  // 1 px per degree, elevation ±60°
    std::vector<std::uint8_t> pixels(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) pixels[static_cast<std::size_t>(y * kWidth + x)] = static_cast<std::uint8_t>(x % 100 + y);
    test::TempDir dir;
    std::string error;
    REQUIRE(io::write_png(dir.file("world.png"), kWidth, kHeight, 1, pixels.data(), error));

    const std::optional<Panorama> p = Panorama::load_png(dir.file("world.png"), error);
    REQUIRE(p);
    CHECK(p->width() == kWidth);
    CHECK(p->height() == kHeight);
    // Column x's centre looks at azimuth x + 0.5 − 180°, row y's at elevation 60° − y − 0.5.
    CHECK(p->grey((10.5 - 180.0) * kRadPerDeg, (60.0 - 20.5) * kRadPerDeg) == Approx(10 + 20));
    CHECK(p->grey((11.0 - 180.0) * kRadPerDeg, (60.0 - 20.5) * kRadPerDeg) == Approx(10.5 + 20));  // between columns
    CHECK(p->grey((10.5 - 180.0) * kRadPerDeg, (60.0 - 21.0) * kRadPerDeg) == Approx(10 + 20.5));  // between rows

    CHECK_FALSE(Panorama::load_png(dir.file("missing.png"), error));
    CHECK_FALSE(error.empty());
}
