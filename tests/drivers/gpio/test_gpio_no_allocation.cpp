// SPDX-License-Identifier: Apache-2.0
// write() and read() of both GPIO drivers allocate nothing on the frame thread.
#include <catch2/catch.hpp>

#include "drivers/gpio/fake_pwm_channel.hpp"
#include "drivers/gpio/pwm_servo.hpp"
#include "gpio_rig.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"

using namespace rays;
using namespace rays::test;

TEST_CASE("gpio-stepper and pwm-servo write and read without allocating", "[gpio][no_allocation]") {
    if (!kAllocationCounting) skip("allocation counting runs in the Release configuration, not under the sanitizers");
    StepperRig rig;
    gpio::FakePwmChannel pan, tilt;
    std::string error;
    auto servo = gpio::make_pwm_servo_driver(gpio::PwmSettings{}, rig.clock, pan, tilt, error);
    REQUIRE(servo != nullptr);
    REQUIRE(servo->configure().ok);
    REQUIRE(servo->activate().ok);
    ptu::PtuState state;
    bool ok = true;
    long allocations = 0;
    for (int frame = 0; frame < 300; ++frame) {
        const ptu::CommandMode mode = frame % 100 < 70 ? ptu::CommandMode::Velocity : ptu::CommandMode::Position;
        const double value = (frame / 30) % 2 == 0 ? 0.5 : -0.5;
        {
            CountingScope counting;
            ok = rig.driver->write(command(mode, value, -value), rig.clock.now()).ok && ok;
            ok = rig.driver->read(state, rig.clock.now()).ok && ok;
            ok = servo->write(command(mode, value, -value), rig.clock.now()).ok && ok;
            ok = servo->read(state, rig.clock.now()).ok && ok;
            allocations += counted_allocations();
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(3));
    }
    CHECK(ok);
    CHECK(allocations == 0);
    CHECK(rig.lines.edge_count() > 0);
}
