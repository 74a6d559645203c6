// SPDX-License-Identifier: Apache-2.0
// The frame path through the drivers allocates nothing: PtuLimiter::write/read over a MockPtu, for
// 1000 frames of changing commands. This binary counts operator new (tests/io/allocation_counter).
#include <catch2/catch.hpp>

#include "allocation_counter.hpp"
#include "limiter_rig.hpp"
#include "support/skip.hpp"

TEST_CASE("PtuLimiter and MockPtu write and read without allocating", "[no_allocation]") {
#ifdef RAYS_SANITIZED
    rays::test::skip("allocation counting runs in the Release configuration, not under the sanitizers");
#else
    using namespace rays::ptu;
    const PtuLimits limits = rays::test::symmetric_limits(-1.0, 1.0, 1.0, 5.0);
    rays::test::LimiterRig rig(rays::test::matched_mock(limits, 0.05), limits);
    constexpr int kFrames = 1000;
    PtuState state;
    bool all_ok = true;
    const std::size_t before = rays::test::allocations();
    for (int frame = 0; frame < kFrames; ++frame) {
        const double t = frame / 30.0;
        const CommandMode mode = frame % 200 < 150 ? CommandMode::Velocity : CommandMode::Position;
        const double value = mode == CommandMode::Velocity ? ((frame / 40) % 2 == 0 ? 1.0 : -1.0) : 0.3;
        all_ok = rig.limiter.write(rays::test::both_axes(mode, value, -value), rays::test::at_seconds(t)).ok && all_ok;
        all_ok = rig.limiter.read(state, rays::test::at_seconds(t)).ok && all_ok;
    }
    const std::size_t allocated = rays::test::allocations() - before;
    CHECK(all_ok);
    CHECK(allocated == 0);
    CHECK(rig.mock.records().size() == kFrames);
#endif
}
