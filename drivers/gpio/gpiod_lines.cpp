// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/gpiod_lines.hpp"

#include <gpiod.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace rays::gpio {
namespace {

ptu::DriverStatus line_error(const char* what, const std::string& chip, int offset) {
    char text[120];
    std::snprintf(text, sizeof text, "gpio: %s line %d on %s: %s", what, offset, chip.c_str(), std::strerror(errno));
    return ptu::DriverStatus::failure(text);
}

}  // namespace

ptu::DriverStatus GpiodLines::open(const LineRequest& request) {
    close();
    // gpiod_chip_open_lookup takes a name, a path, a number or a label (libgpiod 1.6 core API).
    chip_ = gpiod_chip_open_lookup(request.chip.c_str());
    if (chip_ == nullptr) {
        char text[120];
        std::snprintf(text, sizeof text, "gpio: cannot open chip %s: %s", request.chip.c_str(), std::strerror(errno));
        return ptu::DriverStatus::failure(text);
    }
    const char* consumer = request.consumer.c_str();
    for (const OutputLine& output : request.outputs) {
        gpiod_line* line = gpiod_chip_get_line(chip_, static_cast<unsigned>(output.offset));
        if (line == nullptr || gpiod_line_request_output(line, consumer, output.initial_level ? 1 : 0) != 0) {
            ptu::DriverStatus status = line_error("cannot request output", request.chip, output.offset);
            close();
            return status;
        }
        outputs_.push_back(line);
    }
    for (int offset : request.inputs) {
        gpiod_line* line = gpiod_chip_get_line(chip_, static_cast<unsigned>(offset));
        if (line == nullptr || gpiod_line_request_input(line, consumer) != 0) {
            ptu::DriverStatus status = line_error("cannot request input", request.chip, offset);
            close();
            return status;
        }
        inputs_.push_back(line);
    }
    return ptu::DriverStatus::success();
}

void GpiodLines::close() {
    for (gpiod_line* line : outputs_) gpiod_line_release(line);
    for (gpiod_line* line : inputs_) gpiod_line_release(line);
    outputs_.clear();
    inputs_.clear();
    if (chip_ != nullptr) gpiod_chip_close(chip_);
    chip_ = nullptr;
}

bool GpiodLines::set(std::size_t output, bool level, TimePoint& at) {
    const bool ok = gpiod_line_set_value(outputs_[output], level ? 1 : 0) == 0;
    at = MonoClock::now();  // steady_clock is CLOCK_MONOTONIC on Linux
    return ok;
}

bool GpiodLines::get(std::size_t input, bool& level, TimePoint& at) {
    const int value = gpiod_line_get_value(inputs_[input]);
    at = MonoClock::now();
    level = value == 1;
    return value >= 0;
}

}  // namespace rays::gpio
