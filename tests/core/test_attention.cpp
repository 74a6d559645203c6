// SPDX-License-Identifier: Apache-2.0
// The attention module (§4.1): which contour changes count as a lost target.
#include <catch2/catch.hpp>

#include "core/attention.hpp"

namespace {

using rays::Attention;
using rays::AttentionTunables;
using rays::Contour;
using rays::Point;

// A contour of the given area centred at (64, 64), with every ray on an edge.
Contour contour_of_area(double area) {
    Contour c{rays::TrackerCapacity{}};
    c.size = 64;
    c.area = area;
    c.centroid = {64, 64};
    return c;
}

}  // namespace

TEST_CASE("Attention: a sudden growth or shrink of the contour means a lost target", "[attention]") {
    Attention attention;
    const AttentionTunables limits;
    for (int i = 0; i < 10; ++i) REQUIRE(attention.check(contour_of_area(400), {64, 64}, limits) == nullptr);
    CHECK(attention.check(contour_of_area(400 * (1.0 + limits.max_area_change + 0.2)), {64, 64}, limits) != nullptr);
    CHECK(attention.check(contour_of_area(400 * (1.0 - limits.max_area_change - 0.2)), {64, 64}, limits) != nullptr);
}

TEST_CASE("Attention: the target showing whole again after a part was hidden is no jump", "[attention]") {
    Attention attention;
    const AttentionTunables limits;
    for (int i = 0; i < 10; ++i) REQUIRE(attention.check(contour_of_area(400), {64, 64}, limits) == nullptr);
    // An occluder hides half of the target for a while: the running area settles at the half.
    for (int i = 0; i < 10; ++i) REQUIRE(attention.check(contour_of_area(200), {64, 64}, limits) == nullptr);
    // The whole target shows again: double the running area, but the area it had before.
    CHECK(attention.check(contour_of_area(400), {64, 64}, limits) == nullptr);
    // Growing past both the running and the whole area is still a jump.
    for (int i = 0; i < 10; ++i) REQUIRE(attention.check(contour_of_area(200), {64, 64}, limits) == nullptr);
    CHECK(attention.check(contour_of_area(900), {64, 64}, limits) != nullptr);
}

TEST_CASE("Attention: the whole area follows a target that grows slowly", "[attention]") {
    Attention attention;
    const AttentionTunables limits;
    double area = 400;
    for (int i = 0; i < 60; ++i, area *= 1.03) REQUIRE(attention.check(contour_of_area(area), {64, 64}, limits) == nullptr);
    // Now about 5.9 times the start: half hidden, then whole again, is still accepted.
    for (int i = 0; i < 10; ++i) REQUIRE(attention.check(contour_of_area(area / 2), {64, 64}, limits) == nullptr);
    CHECK(attention.check(contour_of_area(area), {64, 64}, limits) == nullptr);
}
