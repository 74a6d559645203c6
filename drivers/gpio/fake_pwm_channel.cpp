// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/fake_pwm_channel.hpp"

namespace rays::gpio {

FakePwmChannel::FakePwmChannel(std::size_t capacity)
    : writes_(std::make_unique<PwmWrite[]>(capacity)), capacity_(capacity) {}

bool FakePwmChannel::record(PwmWrite::File file, long value, TimePoint& at) {
    at = MonoClock::now();
    if (failing_) return false;
    if (count_ < capacity_) writes_[count_++] = PwmWrite{file, value, at};
    return true;
}

ptu::DriverStatus FakePwmChannel::open(long period_ns) {
    std::lock_guard lock(mutex_);
    TimePoint at;
    if (!record(PwmWrite::File::Period, period_ns, at)) return ptu::DriverStatus::failure("pwm: fake channel unavailable");
    period_ = period_ns;
    open_ = true;
    return ptu::DriverStatus::success();
}

void FakePwmChannel::close() {
    std::lock_guard lock(mutex_);
    open_ = false;
}

bool FakePwmChannel::set_duty_ns(long duty_ns, TimePoint& at) {
    std::lock_guard lock(mutex_);
    if (!open_ || duty_ns > period_) {
        at = MonoClock::now();
        return false;
    }
    if (!record(PwmWrite::File::Duty, duty_ns, at)) return false;
    duty_ = duty_ns;
    return true;
}

bool FakePwmChannel::set_enabled(bool enabled, TimePoint& at) {
    std::lock_guard lock(mutex_);
    if (!open_) {
        at = MonoClock::now();
        return false;
    }
    if (!record(PwmWrite::File::Enable, enabled ? 1 : 0, at)) return false;
    enabled_ = enabled;
    return true;
}

void FakePwmChannel::set_failing(bool failing) {
    std::lock_guard lock(mutex_);
    failing_ = failing;
}

std::vector<PwmWrite> FakePwmChannel::writes() const {
    std::lock_guard lock(mutex_);
    return {writes_.get(), writes_.get() + count_};
}

long FakePwmChannel::duty_ns() const {
    std::lock_guard lock(mutex_);
    return duty_;
}

long FakePwmChannel::period_ns() const {
    std::lock_guard lock(mutex_);
    return period_;
}

bool FakePwmChannel::enabled() const {
    std::lock_guard lock(mutex_);
    return enabled_;
}

bool FakePwmChannel::is_open() const {
    std::lock_guard lock(mutex_);
    return open_;
}

}  // namespace rays::gpio
