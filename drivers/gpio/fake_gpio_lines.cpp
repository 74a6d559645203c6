// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/fake_gpio_lines.hpp"

namespace rays::gpio {
namespace {

bool valid(int offset) { return offset >= 0 && offset < 64; }

}  // namespace

FakeGpioLines::FakeGpioLines(std::size_t edge_capacity)
    : edges_(std::make_unique<Edge[]>(edge_capacity)), capacity_(edge_capacity) {}

ptu::DriverStatus FakeGpioLines::open(const LineRequest& request) {
    std::lock_guard lock(mutex_);
    if (failing_) return ptu::DriverStatus::failure("gpio: fake chip unavailable");
    for (const OutputLine& output : request.outputs)
        if (!valid(output.offset)) return ptu::DriverStatus::failure("gpio: fake chip has lines 0..63");
    for (int input : request.inputs)
        if (!valid(input)) return ptu::DriverStatus::failure("gpio: fake chip has lines 0..63");
    request_ = request;
    for (const OutputLine& output : request.outputs) outputs_[static_cast<std::size_t>(output.offset)] = output.initial_level;
    open_ = true;
    ++open_count_;
    return ptu::DriverStatus::success();
}

void FakeGpioLines::close() {
    std::lock_guard lock(mutex_);
    open_ = false;
}

FakeGpioLines::StepCounter* FakeGpioLines::counter_for_step(int offset) {
    for (std::size_t i = 0; i < counter_count_; ++i)
        if (counters_[i].step == offset) return &counters_[i];
    return nullptr;
}

bool FakeGpioLines::set(std::size_t output, bool level, TimePoint& at) {
    std::lock_guard lock(mutex_);
    at = MonoClock::now();
    if (!open_ || failing_ || output >= request_.outputs.size()) return false;
    const int offset = request_.outputs[output].offset;
    bool& current = outputs_[static_cast<std::size_t>(offset)];
    if (current == level) return true;  // no edge
    current = level;
    if (count_ < capacity_) edges_[count_++] = Edge{offset, level, at};
    else ++dropped_;
    if (StepCounter* counter = counter_for_step(offset); counter != nullptr && level)
        counter->position += outputs_[static_cast<std::size_t>(counter->dir)] ? 1 : -1;
    return true;
}

bool FakeGpioLines::input_level(int offset) const {
    for (const SimulatedSwitch& simulated : switches_) {
        if (simulated.input != offset) continue;
        long position = 0;
        for (std::size_t i = 0; i < counter_count_; ++i)
            if (counters_[i].step == simulated.step) position = counters_[i].position;
        const bool active = simulated.below ? position <= simulated.trip_steps : position >= simulated.trip_steps;
        return active == simulated.active_level;
    }
    return inputs_[static_cast<std::size_t>(offset)];
}

bool FakeGpioLines::get(std::size_t input, bool& level, TimePoint& at) {
    std::lock_guard lock(mutex_);
    at = MonoClock::now();
    if (!open_ || failing_ || input >= request_.inputs.size()) return false;
    level = input_level(request_.inputs[input]);
    return true;
}

void FakeGpioLines::set_input(int offset, bool level) {
    std::lock_guard lock(mutex_);
    if (valid(offset)) inputs_[static_cast<std::size_t>(offset)] = level;
}

void FakeGpioLines::add_motor(int step, int dir) {
    std::lock_guard lock(mutex_);
    if (valid(step) && valid(dir) && counter_for_step(step) == nullptr && counter_count_ < kMaxLines)
        counters_[counter_count_++] = StepCounter{step, dir, 0};
}

void FakeGpioLines::add_switch(const SimulatedSwitch& simulated) {
    add_motor(simulated.step, simulated.dir);
    std::lock_guard lock(mutex_);
    switches_.push_back(simulated);
}

void FakeGpioLines::set_failing(bool failing) {
    std::lock_guard lock(mutex_);
    failing_ = failing;
}

bool FakeGpioLines::is_open() const {
    std::lock_guard lock(mutex_);
    return open_;
}

int FakeGpioLines::open_count() const {
    std::lock_guard lock(mutex_);
    return open_count_;
}

std::vector<Edge> FakeGpioLines::edges() const {
    std::lock_guard lock(mutex_);
    return {edges_.get(), edges_.get() + count_};
}

std::vector<Edge> FakeGpioLines::edges_of(int offset) const {
    std::lock_guard lock(mutex_);
    std::vector<Edge> found;
    for (std::size_t i = 0; i < count_; ++i)
        if (edges_[i].offset == offset) found.push_back(edges_[i]);
    return found;
}

std::size_t FakeGpioLines::edge_count() const {
    std::lock_guard lock(mutex_);
    return count_;
}

std::size_t FakeGpioLines::dropped_edges() const {
    std::lock_guard lock(mutex_);
    return dropped_;
}

long FakeGpioLines::steps(int step_offset) const {
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < counter_count_; ++i)
        if (counters_[i].step == step_offset) return counters_[i].position;
    return 0;
}

bool FakeGpioLines::level(int output_offset) const {
    std::lock_guard lock(mutex_);
    return valid(output_offset) && outputs_[static_cast<std::size_t>(output_offset)];
}

}  // namespace rays::gpio
