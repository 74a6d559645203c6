// SPDX-License-Identifier: Apache-2.0
// A simulated PWM channel: records every write (period, duty cycle, enable) with the time it was made
// in a buffer sized at construction, and fails on demand. Thread-safe (the driver's I/O thread writes
// while the test reads).
#pragma once
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "drivers/gpio/pwm_channel.hpp"

namespace rays::gpio {

struct PwmWrite {
    enum class File { Period, Duty, Enable };
    File file = File::Duty;
    long value = 0;
    TimePoint time{};
};

class FakePwmChannel final : public PwmChannel {
public:
    explicit FakePwmChannel(std::size_t capacity = 1 << 16);

    ptu::DriverStatus open(long period_ns) override;
    void close() override;
    bool set_duty_ns(long duty_ns, TimePoint& at) override;
    bool set_enabled(bool enabled, TimePoint& at) override;

    void set_failing(bool failing);
    std::vector<PwmWrite> writes() const;
    long duty_ns() const;  // the current values, as the hardware has them
    long period_ns() const;
    bool enabled() const;
    bool is_open() const;

private:
    bool record(PwmWrite::File file, long value, TimePoint& at);

    mutable std::mutex mutex_;
    std::unique_ptr<PwmWrite[]> writes_;
    std::size_t capacity_ = 0;
    std::size_t count_ = 0;
    bool failing_ = false;
    bool open_ = false;
    long period_ = 0;
    long duty_ = 0;
    bool enabled_ = false;
};

}  // namespace rays::gpio
