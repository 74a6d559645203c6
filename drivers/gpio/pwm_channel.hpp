// SPDX-License-Identifier: Apache-2.0
// The seam under the RC-servo driver: one hardware PWM channel (the kernel's PWM sysfs interface,
// Documentation/ABI/testing/sysfs-class-pwm). SysfsPwmChannel writes the files; FakePwmChannel
// records every write with its time for tests and benches.
#pragma once
#include "core/clock.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::gpio {

class PwmChannel {
public:
    virtual ~PwmChannel() = default;

    // Exports the channel if needed and sets its period; leaves duty cycle and enable as they are
    // (a servo left holding by an earlier run keeps holding). Blocks, may allocate.
    virtual ptu::DriverStatus open(long period_ns) = 0;
    virtual void close() = 0;  // safe when not open; the output keeps running
    // Each a single write of the value; `at` is when it was written. False on an I/O error.
    virtual bool set_duty_ns(long duty_ns, TimePoint& at) = 0;
    virtual bool set_enabled(bool enabled, TimePoint& at) = 0;
};

}  // namespace rays::gpio
