// SPDX-License-Identifier: Apache-2.0
// A simulated GPIO chip for tests and benches: records every output edge with the monotonic time it
// was set (in a buffer sized at construction; later edges are only counted), counts the steps a
// step/dir pair received as a motor would (a rising step edge moves one step, in the direction the
// dir line shows: high = positive), and answers inputs from a level the test sets or from a
// simulated switch that trips when that counted position passes a point.
//
// Thread-safe: the driver's pulse thread sets and gets while the test reads the record.
#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <span>
#include <vector>

#include "drivers/gpio/gpio_lines.hpp"

namespace rays::gpio {

struct Edge {
    int offset = kNoLine;  // the output line
    bool level = false;    // its new level
    TimePoint time{};
};

struct SimulatedSwitch {
    int input = kNoLine;  // the switch's line
    int step = kNoLine;   // the step/dir pair whose counted position trips it
    int dir = kNoLine;
    long trip_steps = 0;     // active at or beyond this position
    bool below = true;       // true: active at positions <= trip_steps, false: >= trip_steps
    bool active_level = true;  // the level the line shows while active
};

class FakeGpioLines final : public GpioLines {
public:
    explicit FakeGpioLines(std::size_t edge_capacity = 1 << 20);

    ptu::DriverStatus open(const LineRequest& request) override;
    void close() override;
    bool set(std::size_t output, bool level, TimePoint& at) override;
    bool get(std::size_t input, bool& level, TimePoint& at) override;

    // Test side.
    void set_input(int offset, bool level);  // a plain input's level (default low)
    void add_motor(int step, int dir);  // counts the steps this pair receives (steps())
    void add_switch(const SimulatedSwitch& simulated);  // also adds its motor
    void set_failing(bool failing);          // I/O and open fail while set
    bool is_open() const;
    int open_count() const;                  // successful opens so far
    std::vector<Edge> edges() const;         // a copy of the record so far
    std::vector<Edge> edges_of(int offset) const;
    std::size_t edge_count() const;
    std::size_t dropped_edges() const;
    long steps(int step_offset) const;       // the position a step/dir pair's motor was moved to
    bool level(int output_offset) const;     // an output's current level

private:
    static constexpr std::size_t kMaxLines = 64;
    struct StepCounter {
        int step = kNoLine;
        int dir = kNoLine;
        long position = 0;
    };

    bool input_level(int offset) const;  // under mutex_
    StepCounter* counter_for_step(int offset);

    mutable std::mutex mutex_;
    LineRequest request_;
    bool open_ = false;
    bool failing_ = false;
    int open_count_ = 0;
    std::array<bool, kMaxLines> outputs_{};
    std::array<bool, kMaxLines> inputs_{};
    std::vector<SimulatedSwitch> switches_;
    std::array<StepCounter, kMaxLines> counters_{};
    std::size_t counter_count_ = 0;
    std::unique_ptr<Edge[]> edges_;
    std::size_t capacity_ = 0;
    std::size_t count_ = 0;
    std::size_t dropped_ = 0;
};

}  // namespace rays::gpio
