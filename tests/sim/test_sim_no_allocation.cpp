// SPDX-License-Identifier: Apache-2.0
// SimCamera::render allocates nothing (support/thread_allocation_counter.hpp counts).
#include <catch2/catch.hpp>

#include "sim_rig.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"

TEST_CASE("rendering allocates nothing", "[no_allocation]") {
#ifdef RAYS_SANITIZED
    rays::test::skip("allocation counting replaces malloc, which AddressSanitizer owns; runs in the Release configuration");
#else
    for (std::string_view name : rays::sim::scenario_names()) {
        const auto camera = rays::test::named_camera(name);
        auto view = std::make_unique<rays::sim::SimView>();
        long allocations = 0;
        {
            rays::test::CountingScope counting;
            for (int i = 0; i < 50; ++i)
                camera->render(i * 0.5, camera->scenario().initial_pan_rad + 0.01 * i, camera->scenario().initial_tilt_rad, *view);
            allocations = rays::test::counted_allocations();
        }
        INFO(name);
        CHECK(allocations == 0);
    }
#endif
}
