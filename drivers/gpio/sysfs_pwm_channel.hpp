// SPDX-License-Identifier: Apache-2.0
// PwmChannel over /sys/class/pwm/pwmchipN/pwmM/{period,duty_cycle,enable} (export through
// pwmchipN/export). duty_cycle and enable stay open, so a change is one pwrite().
#pragma once
#include <string>

#include "drivers/gpio/pwm_channel.hpp"

namespace rays::gpio {

class SysfsPwmChannel final : public PwmChannel {
public:
    // `root` is /sys/class/pwm on a real system (a test lays out a temporary directory like it).
    SysfsPwmChannel(std::string root, int chip, int channel);
    ~SysfsPwmChannel() override { close(); }
    SysfsPwmChannel(const SysfsPwmChannel&) = delete;
    SysfsPwmChannel& operator=(const SysfsPwmChannel&) = delete;

    ptu::DriverStatus open(long period_ns) override;
    void close() override;
    bool set_duty_ns(long duty_ns, TimePoint& at) override;
    bool set_enabled(bool enabled, TimePoint& at) override;

private:
    std::string chip_dir_;
    std::string channel_dir_;
    int channel_;
    int duty_fd_ = -1;
    int enable_fd_ = -1;
};

}  // namespace rays::gpio
