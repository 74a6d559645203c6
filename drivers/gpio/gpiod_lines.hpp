// SPDX-License-Identifier: Apache-2.0
// GpioLines over libgpiod 1.6 (the v1 API of Debian 12's libgpiod-dev): character-device lines
// requested one by one; set/get are one ioctl each (GPIOHANDLE_SET/GET_LINE_VALUES_IOCTL).
#pragma once
#include <vector>

#include "drivers/gpio/gpio_lines.hpp"

struct gpiod_chip;
struct gpiod_line;

namespace rays::gpio {

class GpiodLines final : public GpioLines {
public:
    GpiodLines() = default;
    ~GpiodLines() override { close(); }
    GpiodLines(const GpiodLines&) = delete;
    GpiodLines& operator=(const GpiodLines&) = delete;

    ptu::DriverStatus open(const LineRequest& request) override;
    void close() override;
    bool set(std::size_t output, bool level, TimePoint& at) override;
    bool get(std::size_t input, bool& level, TimePoint& at) override;

private:
    gpiod_chip* chip_ = nullptr;
    std::vector<gpiod_line*> outputs_;
    std::vector<gpiod_line*> inputs_;
};

}  // namespace rays::gpio
