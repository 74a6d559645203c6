// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/pulse_engine.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace rays::gpio {
namespace {

const char* axis_name(std::size_t axis) { return axis == 0 ? "pan" : "tilt"; }

TimePoint::duration seconds(double s) {
    return std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(s));
}

}  // namespace

PulseEngine::PulseEngine(const StepperConfig& config, GpioLines& lines, const Clock& clock)
    : config_(config),
      lines_(lines),
      clock_(clock),
      axes_{StepAxis(config.axes[0], config.max_step_rate_hz, config.dir_setup_s),
            StepAxis(config.axes[1], config.max_step_rate_hz, config.dir_setup_s)},
      homing_{Homing(config.axes[0], config.wiring[0].home_side, config.homing_timeout_s),
              Homing(config.axes[1], config.wiring[1].home_side, config.homing_timeout_s)} {}

void PulseEngine::start() {
    if (thread_.joinable()) return;
    quit_.store(false);
    publish(clock_.now());  // the axes as they start: no reader ever sees the slot's empty value
    thread_ = std::thread([this] { run(); });
}

void PulseEngine::stop() {
    quit_.store(true);
    if (thread_.joinable()) thread_.join();
}

void PulseEngine::apply_realtime() {
    // A thread under normal scheduling wakes up to its timer slack (50 µs by default) after the time
    // it asked for; the pulse thread asks for its wake-ups as exact as the kernel gives them.
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    if (config_.rt_priority <= 0) {
        std::snprintf(realtime_, sizeof realtime_, "normal scheduling");
    } else {
        sched_param param{};
        param.sched_priority = config_.rt_priority;
        const int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param);
        if (error == 0) std::snprintf(realtime_, sizeof realtime_, "SCHED_FIFO %d", config_.rt_priority);
        else std::snprintf(realtime_, sizeof realtime_, "refused: SCHED_FIFO %d: %s", config_.rt_priority, std::strerror(error));
    }
    realtime_ready_.store(true);
}

void PulseEngine::sleep_until(TimePoint until) {
    // steady_clock is CLOCK_MONOTONIC (libstdc++ on Linux), so its count is the timespec's.
    const auto since_epoch = std::chrono::duration_cast<std::chrono::nanoseconds>(until.time_since_epoch()).count();
    timespec ts{};
    ts.tv_sec = static_cast<time_t>(since_epoch / 1000000000);
    ts.tv_nsec = static_cast<long>(since_epoch % 1000000000);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

void PulseEngine::run() {
    apply_realtime();
    while (!quit_.load(std::memory_order_relaxed)) {
        const TimePoint now = MonoClock::now();
        const TimePoint clock_now = clock_.now();
        commands_.try_read([this](const CommandSlot& slot) { slot_ = slot; });
        if (io_fault_) {
            reopen(now);
        } else if (now >= next_input_poll_) {
            next_input_poll_ = now + kInputPeriod;
            if (poll_inputs(now)) check_faults(clock_now);
        }
        if (!io_fault_) {
            const unsigned long homes = home_requests_.load();
            if (homes != homes_seen_) {
                homes_seen_ = homes;
                start_homing(clock_now);
            }
            const bool want_enabled = active_.load() || !(axes_[0].at_rest() && axes_[1].at_rest());
            if (want_enabled != enabled_ && !drive_enable(want_enabled)) io_failed(now);
        }
        if (!io_fault_ && !edges(now, clock_now)) io_failed(MonoClock::now());
        publish(clock_now);
        TimePoint wake = std::min(next_input_poll_, MonoClock::now() + kInputPeriod);
        if (io_fault_) wake = std::min(next_reopen_, MonoClock::now() + std::chrono::milliseconds(10));
        TimePoint edge = TimePoint::max();
        for (const StepAxis& axis : axes_) edge = std::min(edge, axis.due());
        if (edge <= wake) wake_before(edge);
        else sleep_until(wake);
    }
}

void PulseEngine::wake_before(TimePoint due) {
    // Wake-ups come late by the kernel's latency (tens of µs even under SCHED_FIFO on some machines), and
    // a late edge costs the axis speed (step_axis.hpp). So the thread sleeps until a lead before the
    // edge, and edges() spins the rest of the way right before setting the line. The lead follows the
    // wake-up latency's upper tail: it rises by an eighth of any excess and falls by a 512th of any
    // margin, within kMaxWakeLead.
    const TimePoint target = due - wake_lead_;
    sleep_until(target);
    const auto late = MonoClock::now() - target;
    if (late > wake_lead_) wake_lead_ += (late - wake_lead_) / 8;
    else wake_lead_ -= (wake_lead_ - late) / 512;
    wake_lead_ = std::clamp<TimePoint::duration>(wake_lead_, TimePoint::duration::zero(), kMaxWakeLead);
}

void PulseEngine::spin_until(TimePoint due) {
    while (MonoClock::now() < due) {
        // spin: shorter than a sleep's wake-up latency
    }
}

bool PulseEngine::switch_active(int input) const { return input != kNone && inputs_[static_cast<std::size_t>(input)]; }

bool PulseEngine::poll_inputs(TimePoint now) {
    for (std::size_t i = 0; i < config_.request.inputs.size(); ++i) {
        bool level = false;
        TimePoint at;
        if (!lines_.get(i, level, at)) {
            io_failed(now);
            return false;
        }
        const bool active_low = static_cast<int>(i) == config_.estop ? config_.estop_active_low : config_.limit_active_low;
        inputs_[i] = level != active_low;
    }
    return true;
}

void PulseEngine::fault(const char* message) {
    if (status_.ok) status_ = ptu::DriverStatus::failure(message);
}

void PulseEngine::check_faults(TimePoint clock_now) {
    const bool estop = switch_active(config_.estop);
    if (estop && !estop_) {
        for (std::size_t a = 0; a < ptu::kAxes; ++a) {
            axes_[a].halt();
            homing_[a].cancel();
        }
    }
    if (!estop && estop_) hold_since_ = clock_now;
    estop_ = estop;
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        if (homing_[a].running()) continue;  // homing handles its own switches
        const bool hit = switch_active(config_.wiring[a].limit_min) || switch_active(config_.wiring[a].limit_max);
        if (hit && !limit_fault_[a]) {
            axes_[a].halt();
            for (Homing& homing : homing_) homing.cancel();
        }
        if (!hit && limit_fault_[a]) hold_since_ = clock_now;
        limit_fault_[a] = hit;
    }
    // The status names the first fault still present; it clears with the last one.
    status_ = ptu::DriverStatus::success();
    if (estop_) fault("gpio: E-stop asserted: all axes stopped");
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        if (!limit_fault_[a]) continue;
        char text[100];
        std::snprintf(text, sizeof text, "gpio: %s %s limit switch hit: axes stopped", axis_name(a),
                      switch_active(config_.wiring[a].limit_min) ? "min" : "max");
        fault(text);
    }
    if (homing_fault_) fault(homing_failure_);
}

void PulseEngine::start_homing(TimePoint clock_now) {
    if (estop_) return;
    homing_fault_ = false;
    limit_fault_ = {};
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        homing_[a].start(clock_now);
        homed_[a] = false;
    }
    check_faults(clock_now);
}

AxisGoal PulseEngine::homing_goal(std::size_t a, TimePoint clock_now) {
    const AxisWiring& wiring = config_.wiring[a];
    const int home = wiring.home_side < 0 ? wiring.limit_min : wiring.limit_max;
    const int opposite = wiring.home_side < 0 ? wiring.limit_max : wiring.limit_min;
    const Homing::Step step = homing_[a].update(switch_active(home), switch_active(opposite), axes_[a], clock_now);
    if (step.finished) {
        axes_[a].set_position(config_.axes[a].home_offset_steps);
        homed_[a] = true;
        hold_since_ = clock_now;  // the command stream of before homing does not move the axes
    }
    if (step.failure != nullptr) {
        homing_fault_ = true;
        for (Homing& homing : homing_) homing.cancel();
        std::snprintf(homing_failure_, sizeof homing_failure_, "gpio: %s %s: axes stopped, home again", axis_name(a),
                      step.failure);
        fault(homing_failure_);
    }
    return step.goal;
}

AxisGoal PulseEngine::goal_for(std::size_t a, TimePoint now, TimePoint clock_now) {
    (void)now;
    if (estop_ || limit_fault_[a]) return AxisGoal::halt();
    if (homing_[a].running()) return homing_goal(a, clock_now);
    if (homing_[0].running() || homing_[1].running() || !status_.ok) return AxisGoal::stop();
    if (!active_.load() || (config_.require_homing && !homed_[a])) return AxisGoal::stop();
    if (!slot_.valid || slot_.written < hold_since_ || clock_now - slot_.written > seconds(config_.command_timeout_s))
        return AxisGoal::stop();
    const ptu::AxisCommand& command = slot_.command.axes[a];
    const AxisKinematics& kinematics = config_.axes[a];
    if (!std::isfinite(command.value)) return AxisGoal::stop();
    if (command.mode == ptu::CommandMode::Velocity)
        return {AxisGoal::Kind::Velocity, command.value * kinematics.steps_per_rad, 0, kinematics.max_speed};
    const double target = std::clamp(command.value * kinematics.steps_per_rad, -1e15, 1e15);
    return {AxisGoal::Kind::Position, 0.0, std::lround(target), kinematics.max_speed};
}

bool PulseEngine::drive_enable(bool on) {
    for (int output : config_.enables) {
        if (output == kNone) continue;
        TimePoint at;
        if (!lines_.set(static_cast<std::size_t>(output), on != config_.enable_active_low, at)) return false;
    }
    enabled_ = on;
    return true;
}

bool PulseEngine::step(std::size_t a) {
    const std::size_t line = config_.wiring[a].step;
    spin_until(axes_[a].due());
    TimePoint high;
    if (!lines_.set(line, true, high)) return false;
    const double late_us = std::chrono::duration<double, std::micro>(high - axes_[a].due()).count();
    max_late_us_ = std::max(max_late_us_, late_us);
    lateness_.add(late_us);
    axes_[a].stepped(high);
    const TimePoint release = high + seconds(config_.pulse_width_s);
    spin_until(release);
    TimePoint low;
    return lines_.set(line, false, low);
}

bool PulseEngine::edges(TimePoint now, TimePoint clock_now) {
    // Several edges may fall due in one wake-up (two axes, a DIR then its STEP); each replans.
    for (int round = 0; round < 8; ++round) {
        bool acted = false;
        for (std::size_t a = 0; a < ptu::kAxes; ++a) {
            axes_[a].plan(goal_for(a, now, clock_now), now);
            if (axes_[a].due() > now + wake_lead_) continue;  // within the lead: spun to in time
            acted = true;
            if (axes_[a].action() == StepAxis::Action::SetDir) {
                spin_until(axes_[a].due());
                TimePoint at;
                const int direction = axes_[a].wanted_direction();
                if (!lines_.set(config_.wiring[a].dir, direction > 0, at)) return false;
                axes_[a].dir_set(direction, at);
            } else if (!step(a)) {
                return false;
            }
        }
        if (!acted) return true;
        now = MonoClock::now();
    }
    return true;
}

void PulseEngine::io_failed(TimePoint now) {
    if (io_fault_) return;
    io_fault_ = true;
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        axes_[a].halt();
        homing_[a].cancel();
        homed_[a] = false;  // an edge may have been lost: the count is no longer the position
    }
    lines_.close();
    enabled_ = false;
    status_ = ptu::DriverStatus::failure("gpio: line I/O failed: axes stopped, reopening the chip");
    backoff_ = kFirstBackoff;
    next_reopen_ = now + backoff_;
}

void PulseEngine::reopen(TimePoint now) {
    if (now < next_reopen_) return;
    if (!lines_.open(config_.request).ok) {
        backoff_ = std::min<TimePoint::duration>(backoff_ * 2, kLastBackoff);
        next_reopen_ = now + backoff_;
        return;
    }
    ++reopens_;
    io_fault_ = false;
    for (StepAxis& axis : axes_) axis.dir_set(-1, now);  // reopened outputs start low
    hold_since_ = clock_.now();
    next_input_poll_ = now;
    status_ = ptu::DriverStatus::success();
}

void PulseEngine::publish(TimePoint clock_now) {
    reports_.try_publish([&](EngineReport& report) {
        for (std::size_t a = 0; a < ptu::kAxes; ++a) {
            const double spr = config_.axes[a].steps_per_rad;
            const bool faulted = io_fault_ || estop_ || limit_fault_[a] || homing_fault_;
            report.state.axes[a] = ptu::AxisState{static_cast<double>(axes_[a].position()) / spr,
                                                  axes_[a].velocity() / spr, enabled_ && !faulted, faulted, homed_[a]};
        }
        report.state.stamp = clock_now;
        report.status = status_;
        report.enabled = enabled_;
        report.at_rest = axes_[0].at_rest() && axes_[1].at_rest();
        report.homing = homing_[0].running() || homing_[1].running();
        report.late_edges = axes_[0].late_edges() + axes_[1].late_edges();
        report.lost_steps = axes_[0].lost_steps() + axes_[1].lost_steps();
        report.max_late_us = max_late_us_;
        report.lateness = lateness_;
        report.reopens = reopens_;
    });
}

}  // namespace rays::gpio
