// SPDX-License-Identifier: Apache-2.0
// write() and read() of the Modbus driver allocate nothing on the calling (frame) thread while the
// I/O thread talks to ptu-sim. This binary counts allocations per thread.
#include <catch2/catch.hpp>

#include "modbus_rig.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"

using namespace rays;
using namespace rays::test;

TEST_CASE("modbus write and read allocate nothing", "[modbus][no_allocation]") {
    if (!kAllocationCounting) skip("allocation counting runs in the Release configuration, not under the sanitizers");
    // ptu-sim is another process: on a loaded machine it may answer later than the fault tests'
    // 40 ms, and a fault here is not what this test is about.
    Rig rig("no_alloc", "tcp", custom_map_ini(), "", 2000);
    REQUIRE(rig.up());
    ptu::PtuState state;
    bool all_ok = true;
    long allocated = 0;
    {
        CountingScope counting;
        for (int frame = 0; frame < 300; ++frame) {
            const double v = (frame / 30) % 2 == 0 ? 0.3 : -0.3;
            all_ok = rig.driver->write(velocities(v, -v), rig.clock.now()).ok && all_ok;
            all_ok = rig.driver->read(state, rig.clock.now()).ok && all_ok;
            std::this_thread::sleep_for(std::chrono::milliseconds(3));
        }
        allocated = counted_allocations();
    }
    CHECK(all_ok);
    CHECK(allocated == 0);
}
