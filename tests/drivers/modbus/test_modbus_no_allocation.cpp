// SPDX-License-Identifier: Apache-2.0
// write() and read() of the Modbus driver allocate nothing on the calling (frame) thread while the
// I/O thread talks to ptu-sim. This binary counts allocations per thread.
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

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
    long allocated = 0;
    int first_failed_frame = -1;  // and its status (a fixed array: keeping it allocates nothing)
    ptu::DriverStatus first_failure;
    {
        CountingScope counting;
        for (int frame = 0; frame < 300; ++frame) {
            const double v = (frame / 30) % 2 == 0 ? 0.3 : -0.3;
            const ptu::DriverStatus written = rig.driver->write(velocities(v, -v), rig.clock.now());
            const ptu::DriverStatus read = rig.driver->read(state, rig.clock.now());
            if (first_failed_frame < 0 && (!written.ok || !read.ok)) {
                first_failed_frame = frame;
                first_failure = written.ok ? read : written;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(3));
        }
        allocated = counted_allocations();
    }
    // The I/O thread talked to the unit meanwhile: it received both velocities on both axes (0.3 rad/s
    // at 1,000 counts per rad/s, high word first). A reply missed under load is the fault path, which
    // allocates nothing on this thread either; the fault tests check that path's behaviour.
    const std::vector<Received> rows = rig.received();
    INFO("first failed write or read at frame " << first_failed_frame << ": " << first_failure.what());
    for (const int slave : {1, 2}) {
        const std::vector<std::int32_t> received = values32(rows, slave, 0);
        for (const std::int32_t wanted : {300, -300}) {
            INFO("slave " << slave << ", velocity " << wanted);
            CHECK(std::count(received.begin(), received.end(), wanted) >= 1);
        }
    }
    CHECK(allocated == 0);
}
