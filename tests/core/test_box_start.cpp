// SPDX-License-Identifier: Apache-2.0
// Where a box start's rays begin (core/box_start.hpp), for a crescent whose colours are known: the
// middle of the box round it lies in its hollow. (On real footage: davis-blackswan from its box, whose
// middle is on the water beside the swan's neck; README, "A box start's rays from the target".)
#include <catch2/catch.hpp>

#include <cmath>

#include "core/box_start.hpp"

namespace {

using rays::Box;
using rays::BoxStartPoint;
using rays::LikelihoodMap;
using rays::Point;

// A disc of radius 16 round (50, 64) less a disc of radius 9 round (56, 64): a crescent opening to the
// right, 13 px thick at its back (its deepest point about (40.5, 64)). The box round it has the first
// disc's centre, which lies in the hollow.
struct Crescent {
    static constexpr double kX = 50.0, kY = 64.0, kOuter = 16.0, kInner = 9.0, kHollowShift = 6.0;
    static bool on(double px, double py) {
        return std::hypot(px - kX, py - kY) <= kOuter && std::hypot(px - kX - kHollowShift, py - kY) > kInner;
    }
    static Box box() { return {kX - kOuter, kY - kOuter, 2 * kOuter + 1, 2 * kOuter + 1}; }
};

// Log-odds +2 on the cells whose centres lie on the crescent, −2 elsewhere.
LikelihoodMap crescent_colours() {
    LikelihoodMap map;
    for (int j = 0; j < LikelihoodMap::kSize; ++j)
        for (int i = 0; i < LikelihoodMap::kSize; ++i)
            map.log_odds[static_cast<std::size_t>(j * LikelihoodMap::kSize + i)] =
                Crescent::on(2 * i + 0.5, 2 * j + 0.5) ? 2.0f : -2.0f;
    return map;
}

}  // namespace

TEST_CASE("A box whose centre the colours call background starts at the deepest of its target's cells", "[box]") {
    BoxStartPoint start;
    const Box box = Crescent::box();
    REQUIRE_FALSE(Crescent::on(box.centre().x, box.centre().y));
    const Point m = start.find(box, crescent_colours());
    CAPTURE(m.x, m.y);
    CHECK(Crescent::on(m.x, m.y));
    CHECK(std::hypot(m.x - (Crescent::kX - 9.5), m.y - Crescent::kY) <= 3.0);
}

TEST_CASE("A box whose centre the colours call the target, or with nothing of the target's colours, starts at its centre", "[box]") {
    BoxStartPoint start;
    const Box back{Crescent::kX - 16.0, Crescent::kY - 6.0, 12.0, 13.0};  // round the crescent's back
    REQUIRE(Crescent::on(back.centre().x, back.centre().y));
    const Point on_target = start.find(back, crescent_colours());
    CHECK(on_target.x == back.centre().x);
    CHECK(on_target.y == back.centre().y);

    LikelihoodMap background;
    background.log_odds.fill(-2.0f);
    const Point none = start.find(Crescent::box(), background);
    CHECK(none.x == Crescent::box().centre().x);
    CHECK(none.y == Crescent::box().centre().y);
}
