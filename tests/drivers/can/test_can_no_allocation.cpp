// SPDX-License-Identifier: Apache-2.0
// write() and read() of the CAN drivers allocate nothing on the frame-loop thread.
#include <catch2/catch.hpp>

#include "canopen_rig.hpp"
#include "odrive_rig.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"

using namespace rays;

TEST_CASE("canopen: write and read allocate nothing", "[canopen][no_allocation]") {
    if (!test::kAllocationCounting) test::skip("allocation counting runs in the Release build, not under ASan");
    test::CanopenRig rig;
    REQUIRE(rig.driver->configure().ok);
    REQUIRE(rig.driver->activate().ok);
    ptu::PtuState state;
    long allocations = 0;
    {
        test::CountingScope counting;
        for (int frame = 0; frame < 1000; ++frame) {
            const double v = frame % 2 == 0 ? 0.2 : -0.2;
            const auto command = frame % 100 < 50 ? test::velocities(v, -v) : test::positions(0.1, -0.1);
            (void)rig.driver->write(command, rig.clock.now());
            (void)rig.driver->read(state, rig.clock.now());
        }
        allocations = test::counted_allocations();
    }
    CHECK(allocations == 0);
    CHECK(state.axes[0].enabled);
    rig.driver->deactivate();
}

TEST_CASE("odrive: write and read allocate nothing", "[odrive][no_allocation]") {
    if (!test::kAllocationCounting) test::skip("allocation counting runs in the Release build, not under ASan");
    test::OdriveRig rig;
    REQUIRE(rig.driver->configure().ok);
    REQUIRE(rig.driver->activate().ok);
    ptu::PtuState state;
    long allocations = 0;
    {
        test::CountingScope counting;
        for (int frame = 0; frame < 1000; ++frame) {
            const double v = frame % 2 == 0 ? 0.2 : -0.2;
            const auto command = frame % 100 < 50 ? test::velocities(v, -v) : test::positions(0.1, -0.1);
            (void)rig.driver->write(command, rig.clock.now());
            (void)rig.driver->read(state, rig.clock.now());
        }
        allocations = test::counted_allocations();
    }
    CHECK(allocations == 0);
    CHECK(state.axes[0].enabled);
    rig.driver->deactivate();
}
