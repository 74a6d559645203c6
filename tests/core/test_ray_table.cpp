// SPDX-License-Identifier: Apache-2.0
// The coarse-to-fine ray order of the any-time algorithm (§2.3, Fig. 6).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/ray_table.hpp"

namespace {

using rays::RayTable;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Largest angular gap between consecutive rays among the first `shot` of the order, round the circle.
double max_gap(const RayTable& table, int shot) {
    std::vector<double> a(shot);
    for (int k = 0; k < shot; ++k) a[k] = table.angle(table.order(k));
    std::sort(a.begin(), a.end());
    double gap = a.front() + kTwoPi - a.back();
    for (int k = 1; k < shot; ++k) gap = std::max(gap, a[k] - a[k - 1]);
    return gap;
}

}  // namespace

TEST_CASE("RayTable level 0 shoots the rays at 0 and pi", "[ray_table]") {
    for (int count : {8, 64, 100, 360, 720}) {
        RayTable table(720);
        table.set_count(count);
        INFO("count " << count);
        REQUIRE(table.level_end(0) == 2);
        CHECK(table.angle(table.order(0)) == Approx(0.0).margin(1e-12));
        CHECK(table.angle(table.order(1)) == Approx(std::numbers::pi));
    }
}

TEST_CASE("RayTable levels double the ray count for powers of two", "[ray_table]") {
    for (int count : {2, 4, 16, 128, 512}) {
        RayTable table(512);
        table.set_count(count);
        INFO("count " << count);
        REQUIRE(table.count() == count);
        REQUIRE((1 << table.levels()) == count);
        for (int level = 0; level < table.levels(); ++level) CHECK(table.level_end(level) == 2 << level);
    }
}

TEST_CASE("RayTable order holds every ray exactly once, spread evenly at every level", "[ray_table]") {
    for (int count : {360, 100, 7, 720, 64}) {
        RayTable table(720);
        table.set_count(count);
        INFO("count " << count);
        REQUIRE(table.count() == count);
        std::vector<int> seen(count, 0);
        for (int k = 0; k < count; ++k) {
            const int i = table.order(k);
            REQUIRE((i >= 0 && i < count));
            ++seen[i];
        }
        CHECK(std::all_of(seen.begin(), seen.end(), [](int s) { return s == 1; }));
        REQUIRE(table.levels() >= 1);
        CHECK(table.level_end(table.levels() - 1) == count);
        for (int level = 0; level < table.levels(); ++level) {
            const int end = table.level_end(level);
            INFO("level " << level << " ends after " << end << " rays");
            if (level > 0) CHECK(end > table.level_end(level - 1));
            CHECK(max_gap(table, end) <= 2.0 * kTwoPi / end + 1e-9);
        }
    }
}

TEST_CASE("RayTable angles are evenly spaced and the cos/sin tables match them", "[ray_table]") {
    RayTable table(720);
    for (int count : {360, 100}) {
        table.set_count(count);
        for (int i = 0; i < count; ++i) {
            INFO("count " << count << ", ray " << i);
            REQUIRE(table.angle(i) == Approx(kTwoPi * i / count).margin(1e-12));
            REQUIRE(table.cos_at(i) == Approx(std::cos(table.angle(i))).margin(1e-12));
            REQUIRE(table.sin_at(i) == Approx(std::sin(table.angle(i))).margin(1e-12));
        }
    }
}

TEST_CASE("RayTable clamps the count to its capacity", "[ray_table]") {
    RayTable table(100);
    CHECK(table.capacity() == 100);
    CHECK(table.count() == 100);
    table.set_count(400);
    CHECK(table.count() == 100);
    table.set_count(1);
    CHECK(table.count() == 2);
}
