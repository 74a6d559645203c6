// SPDX-License-Identifier: Apache-2.0
// The stepper's I/O thread: the only code touching the lines. It generates the step and dir edges of
// both axes (StepAxis schedules; clock_nanosleep(TIMER_ABSTIME) on CLOCK_MONOTONIC waits until a learned
// lead before each edge, a spin the rest of the way; a short spin holds each pulse for pulse_width), polls the limit, home and E-stop inputs every kInputPeriod, runs
// homing, and reopens the chip with backoff after an I/O error. It runs at SCHED_FIFO rt_priority
// when the system allows, and reports whether it does.
//
// Hand-over with the frame loop: the newest command through a LatestValue (newest wins, try_ forms on
// both sides, so neither ever waits), lifecycle and home requests through atomics, the state back
// through another LatestValue. A command older than command_timeout_s, or given before a fault
// cleared, stops the axes (ramped); E-stop, a limit switch and I/O errors stop them at once.
// Without this thread no edge is made at all, so a killed daemon leaves the motors standing.
#pragma once
#include <atomic>
#include <chrono>
#include <thread>

#include "common/latest_value.hpp"
#include "drivers/gpio/gpio_lines.hpp"
#include "drivers/gpio/homing.hpp"
#include "drivers/gpio/lateness_histogram.hpp"
#include "drivers/gpio/step_axis.hpp"
#include "drivers/gpio/stepper_config.hpp"

namespace rays::gpio {

struct CommandSlot {
    ptu::PtuCommand command;
    TimePoint written{};  // on the driver's Clock
    bool valid = false;
};

struct EngineReport {
    ptu::PtuState state;  // positions in rad, stamped on the driver's Clock
    ptu::DriverStatus status;
    bool enabled = false;   // the enable lines are at their active level
    bool at_rest = true;    // both axes
    bool homing = false;
    long late_edges = 0;    // STEP edges more than StepAxis::kJitter late, both axes (each re-planned)
    long lost_steps = 0;    // the plan's steps that lateness dropped, both axes
    double max_late_us = 0.0;  // latest step edge after its due time so far
    LatenessHistogram lateness;  // every STEP edge's time after its due time
    long reopens = 0;
};

class PulseEngine {
public:
    static constexpr std::chrono::microseconds kInputPeriod{200};  // inputs polled (and idle wake-ups) this often
    static constexpr std::chrono::milliseconds kFirstBackoff{500};
    static constexpr std::chrono::seconds kLastBackoff{8};
    static constexpr std::chrono::microseconds kMaxWakeLead{200};  // longest spin before a step edge

    PulseEngine(const StepperConfig& config, GpioLines& lines, const Clock& clock);
    ~PulseEngine() { stop(); }
    PulseEngine(const PulseEngine&) = delete;
    PulseEngine& operator=(const PulseEngine&) = delete;

    void start();  // the lines are open
    void stop();   // joins the thread

    LatestValue<CommandSlot>& commands() { return commands_; }
    const LatestValue<EngineReport>& reports() const { return reports_; }
    void set_active(bool active) { active_.store(active); }  // false: axes ramp to rest, then disabled
    void request_home() { home_requests_.fetch_add(1); }
    // "SCHED_FIFO 80", "normal scheduling" or "refused: …"; empty until the thread has started.
    const char* realtime() const { return realtime_ready_.load() ? realtime_ : ""; }

private:
    void run();
    void apply_realtime();
    bool poll_inputs(TimePoint now);
    bool switch_active(int input) const;
    void check_faults(TimePoint now);
    void start_homing(TimePoint now);
    AxisGoal goal_for(std::size_t axis, TimePoint now, TimePoint clock_now);
    AxisGoal homing_goal(std::size_t axis, TimePoint now);
    bool drive_enable(bool on);
    bool edges(TimePoint now, TimePoint clock_now);
    bool step(std::size_t axis);
    void io_failed(TimePoint now);
    void reopen(TimePoint now);
    void publish(TimePoint clock_now);
    void fault(const char* message);
    static void sleep_until(TimePoint until);
    void wake_before(TimePoint due);
    static void spin_until(TimePoint due);

    StepperConfig config_;
    GpioLines& lines_;
    const Clock& clock_;
    LatestValue<CommandSlot> commands_;
    LatestValue<EngineReport> reports_;
    std::atomic<bool> active_{false};
    std::atomic<bool> quit_{false};
    std::atomic<unsigned long> home_requests_{0};
    std::atomic<bool> realtime_ready_{false};
    char realtime_[100] = {};
    std::thread thread_;

    // Pulse-thread state.
    std::array<StepAxis, ptu::kAxes> axes_;
    std::array<Homing, ptu::kAxes> homing_;
    std::array<bool, ptu::kAxes> homed_{};
    std::array<bool, ptu::kAxes> limit_fault_{};
    std::array<bool, 16> inputs_{};  // by input index, true = active (after the polarity)
    CommandSlot slot_;
    unsigned long homes_seen_ = 0;
    bool enabled_ = false;
    bool estop_ = false;
    bool io_fault_ = false;
    bool homing_fault_ = false;
    char homing_failure_[100] = {};  // why homing failed, while homing_fault_
    ptu::DriverStatus status_;
    TimePoint hold_since_{};  // on the Clock: commands written before this do not move the axes
    TimePoint next_input_poll_{};
    TimePoint next_reopen_{};
    TimePoint::duration backoff_ = kFirstBackoff;
    long reopens_ = 0;
    double max_late_us_ = 0.0;
    LatenessHistogram lateness_;
    TimePoint::duration wake_lead_{};  // how long before a step edge the thread wakes, then spins
};

}  // namespace rays::gpio
