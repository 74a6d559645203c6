// SPDX-License-Identifier: Apache-2.0
// The line-level seam under the GPIO stepper: a chip's output and input lines, each access stamped
// with the monotonic time it happened. GpiodLines (libgpiod) drives real lines; FakeGpioLines records
// every edge for tests. Levels are physical (true = high); active-low wiring is the driver's business.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/clock.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::gpio {

constexpr int kNoLine = -1;  // a line that is not wired

struct OutputLine {
    int offset = kNoLine;  // line offset on the chip
    bool initial_level = false;
};

struct LineRequest {
    std::string chip;                 // "gpiochip0", "/dev/gpiochip0", "0" or the chip's label
    std::string consumer = "raysd";   // shown by gpioinfo
    std::vector<OutputLine> outputs;  // set() addresses them by their index here
    std::vector<int> inputs;          // get() addresses them by their index here
};

class GpioLines {
public:
    virtual ~GpioLines() = default;

    // Opens the chip and requests every line (outputs at their initial level). Blocks, allocates.
    virtual ptu::DriverStatus open(const LineRequest& request) = 0;
    // Releases the lines (they keep their last level) and the chip. Safe when not open.
    virtual void close() = 0;

    // Drives outputs[output] to `level`; `at` is when it was set. False on an I/O error.
    virtual bool set(std::size_t output, bool level, TimePoint& at) = 0;
    // Reads inputs[input]; `at` is when it was read. False on an I/O error.
    virtual bool get(std::size_t input, bool& level, TimePoint& at) = 0;
};

}  // namespace rays::gpio
