// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "control/pose_history.hpp"

using rays::control::PoseHistory;
using rays::control::UnitPose;

TEST_CASE("pose history: the pose between two reports is interpolated, beyond them extrapolated") {
    PoseHistory history;
    CHECK(history.at(1.0).pan == 0.0);  // nothing reported yet: at rest at zero
    history.record({0.00, 0.0, 0.0, 1.0, 0.0});
    history.record({0.04, 0.04, 0.1, 1.0, 2.0});
    history.record({0.08, 0.12, 0.1, 3.0, 0.0});
    const UnitPose mid = history.at(0.06);
    CHECK(mid.pan == Approx(0.08));
    CHECK(mid.tilt == Approx(0.1));
    CHECK(mid.pan_rate == Approx(2.0));
    CHECK(mid.t_s == 0.06);
    CHECK(history.at(0.04).pan == Approx(0.04));
    // After the newest report: at its rate, as the unit was going.
    CHECK(history.at(0.10).pan == Approx(0.12 + 3.0 * 0.02));
    // Before the oldest: back along the oldest's rate.
    CHECK(history.at(-0.02).pan == Approx(-0.02));
}

TEST_CASE("pose history keeps the newest reports when it wraps, and ignores a report older than the newest") {
    PoseHistory history;
    const int n = static_cast<int>(PoseHistory::kCapacity) * 3 + 5;
    for (int k = 0; k < n; ++k) history.record({k * 0.04, k * 0.01, 0.0, 0.25, 0.0});
    const double newest = (n - 1) * 0.04;
    CHECK(history.at(newest - 0.5).pan == Approx((newest - 0.5) / 4));
    CHECK(history.at(newest - 2.5).pan == Approx((newest - 2.5) / 4));
    // Far older than the ring holds: extrapolated from the oldest kept, still on this straight line.
    CHECK(history.at(1.0).pan == Approx(0.25));
    history.record({newest - 1.0, 99.0, 0.0, 0.0, 0.0});
    CHECK(history.at(newest - 1.0).pan == Approx((newest - 1.0) / 4));
}
