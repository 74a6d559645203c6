// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/pwm_servo.hpp"
#include "common/angles.hpp"

#include <time.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>

#include "drivers/gpio/sysfs_pwm_channel.hpp"

namespace rays::gpio {
namespace {

constexpr double kMaxIntegration_s = 0.1;  // a velocity command integrates over at most this much time

TimePoint::duration seconds(double s) {
    return std::chrono::duration_cast<TimePoint::duration>(std::chrono::duration<double>(s));
}

void sleep_until(TimePoint until) {
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(until.time_since_epoch()).count();
    timespec ts{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
    }
}

ServoRange range_of(double min_us, double max_us, double min_deg, double max_deg, double speed_deg_s) {
    return {min_us * 1e3, max_us * 1e3, min_deg * kRadPerDeg, max_deg * kRadPerDeg, speed_deg_s * kRadPerDeg};
}

}  // namespace

bool make_pwm_config(const PwmSettings& s, PwmConfig& config, std::string& error) {
    config = PwmConfig{};
    config.ranges[0] = range_of(s.pan_min_pulse_us, s.pan_max_pulse_us, s.pan_min_angle_deg, s.pan_max_angle_deg, s.pan_speed_deg_s);
    config.ranges[1] = range_of(s.tilt_min_pulse_us, s.tilt_max_pulse_us, s.tilt_min_angle_deg, s.tilt_max_angle_deg, s.tilt_speed_deg_s);
    config.start_rad = {s.pan_start_deg * kRadPerDeg, s.tilt_start_deg * kRadPerDeg};
    config.period_ns = std::lround(s.period_ms * 1e6);
    config.disable_on_deactivate = s.disable_on_deactivate;
    config.command_timeout_s = s.command_timeout_s;
    config.move_speed_rad_s = s.move_speed_deg_s * kRadPerDeg;
    if (s.pan_chip == s.tilt_chip && s.pan_channel == s.tilt_channel) error = "pwm: pan and tilt use the same channel";
    for (const ServoRange& range : config.ranges) {
        if (!(range.min_pulse_ns < range.max_pulse_ns) || !(range.min_rad < range.max_rad))
            error = "pwm: each pulse and angle range needs min < max";
        else if (range.max_pulse_ns >= static_cast<double>(config.period_ns))
            error = "pwm: the longest pulse must be shorter than period_ms";
    }
    return error.empty();
}

PwmServo::PwmServo(const PwmConfig& config, PwmChannel& pan, PwmChannel& tilt, const Clock& clock,
                   std::array<std::unique_ptr<PwmChannel>, 2> owned)
    : config_(config),
      owned_(std::move(owned)),
      channels_{&pan, &tilt},
      clock_(clock),
      servos_{ServoModel(config.ranges[0], config.start_rad[0], clock.now()),
              ServoModel(config.ranges[1], config.start_rad[1], clock.now())} {
    last_.servos = servos_;
}

PwmServo::~PwmServo() {
    if (active_.load()) deactivate();
    quit_.store(true);
    if (thread_.joinable()) thread_.join();
    for (PwmChannel* channel : channels_) channel->close();
}

double PwmServo::command_latency_s() const {
    // The I/O thread's wake-up, then the hardware takes the new duty cycle at the next period.
    return std::chrono::duration<double>(kPeriod).count() + static_cast<double>(config_.period_ns) * 1e-9;
}

ptu::DriverStatus PwmServo::configure() {
    if (active_.load()) return ptu::DriverStatus::failure("pwm: configure while active");
    if (configured_) return ptu::DriverStatus::success();
    for (PwmChannel* channel : channels_)
        if (ptu::DriverStatus status = channel->open(config_.period_ns); !status.ok) return status;
    configured_ = true;
    publish();
    thread_ = std::thread([this] { run(); });
    return ptu::DriverStatus::success();
}

ptu::DriverStatus PwmServo::activate() {
    if (!configured_) return ptu::DriverStatus::failure("pwm: activate before configure");
    active_.store(true);
    for (int i = 0; i < 1000; ++i) {
        const ServoReport now = report();
        if (now.active || !now.status.ok) return now.status;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return ptu::DriverStatus::failure("pwm: the I/O thread did not enable the outputs");
}

void PwmServo::deactivate() {
    active_.store(false);
    written_ = false;
    if (!configured_) return;
    for (int i = 0; i < 1000 && report().active; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(1));
}

ptu::DriverStatus PwmServo::home(TimePoint now) {
    (void)now;
    return ptu::DriverStatus::success();  // a servo knows its absolute angle
}

ptu::DriverStatus PwmServo::write(const ptu::PtuCommand& command, TimePoint now) {
    if (!active_.load()) return ptu::DriverStatus::failure("pwm: write while not active");
    reports_.try_read([this](const ServoReport& report) { last_ = report; });
    const double dt = written_ ? std::clamp(std::chrono::duration<double>(now - last_write_).count(), 0.0, kMaxIntegration_s) : 0.0;
    ServoSlot next;
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        ServoModel servo = last_.servos[a];
        servo.advance(now);
        const ptu::AxisCommand& axis = command.axes[a];
        const double value = std::isfinite(axis.value) ? axis.value : 0.0;
        // A velocity command moves the angle by value·dt; a position command slews toward its target at
        // the move speed (the servo itself would go at its rated speed).
        const double step = axis.mode == ptu::CommandMode::Position
                                ? std::clamp(value - servo.estimate(), -config_.move_speed_rad_s * dt, config_.move_speed_rad_s * dt)
                                : value * dt;
        next.target_rad[a] = servo.clamp(servo.estimate() + step);
    }
    next.written = now;
    next.valid = true;
    commands_.try_publish([&](ServoSlot& slot) { slot = next; });
    last_write_ = now;
    written_ = true;
    return last_.status;
}

ptu::DriverStatus PwmServo::read(ptu::PtuState& state, TimePoint now) {
    if (!configured_) return ptu::DriverStatus::failure("pwm: read before configure");
    reports_.try_read([this](const ServoReport& report) { last_ = report; });
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        ServoModel servo = last_.servos[a];
        servo.advance(now);
        state.axes[a] = ptu::AxisState{servo.estimate(), servo.velocity(), last_.enabled && last_.status.ok,
                                       !last_.status.ok, true};
    }
    state.stamp = now;
    return last_.status;
}

ServoReport PwmServo::report() const {
    ServoReport copy;
    reports_.read([&](const ServoReport& report) { copy = report; });
    return copy;
}

bool PwmServo::set_duty(std::size_t axis, long duty_ns) {
    if (duty_[axis] == duty_ns) return true;
    TimePoint at;
    if (!channels_[axis]->set_duty_ns(duty_ns, at)) return false;
    duty_[axis] = duty_ns;
    return true;
}

bool PwmServo::set_enabled(bool enabled) {
    for (PwmChannel* channel : channels_) {
        TimePoint at;
        if (!channel->set_enabled(enabled, at)) return false;
    }
    enabled_ = enabled;
    return true;
}

bool PwmServo::apply(const ServoSlot& slot, TimePoint now, TimePoint clock_now) {
    const bool active = active_.load();
    const bool fresh = slot.valid && slot.written > applied_ && clock_now - slot.written <= seconds(config_.command_timeout_s);
    const bool stale = !slot.valid || clock_now - slot.written > seconds(config_.command_timeout_s);
    for (std::size_t a = 0; a < ptu::kAxes; ++a) {
        servos_[a].advance(now);
        if (active && fresh) servos_[a].command(slot.target_rad[a], now);
        // Stale commands, deactivate: hold where the servo is estimated to be.
        else if (!active || (stale && !holding_)) servos_[a].command(servos_[a].estimate(), now);
    }
    if (active && fresh) applied_ = slot.written;
    holding_ = active && stale;
    for (std::size_t a = 0; a < ptu::kAxes; ++a)
        if (!set_duty(a, servos_[a].pulse_ns(servos_[a].target()))) return false;
    if (active && !enabled_ && !set_enabled(true)) return false;
    if (!active && applied_active_ && config_.disable_on_deactivate && !set_enabled(false)) return false;
    applied_active_ = active;
    return true;
}

void PwmServo::run() {
    TimePoint wake = MonoClock::now();
    while (!quit_.load()) {
        const TimePoint now = MonoClock::now();
        commands_.try_read([this](const ServoSlot& slot) { slot_ = slot; });
        if (io_fault_) reopen(now);
        if (!io_fault_ && !apply(slot_, now, clock_.now())) io_failed(now, "pwm: duty_cycle or enable write failed: reopening");
        publish();
        wake = std::max(wake + kPeriod, now);
        sleep_until(wake);
    }
}

void PwmServo::io_failed(TimePoint now, const char* what) {
    io_fault_ = true;
    status_ = ptu::DriverStatus::failure(what);
    for (PwmChannel* channel : channels_) channel->close();
    duty_ = {-1, -1};
    enabled_ = false;
    for (ServoModel& servo : servos_) servo.command(servo.estimate(), now);  // the other axis holds too
    backoff_ = kFirstBackoff;
    next_reopen_ = now + backoff_;
}

void PwmServo::reopen(TimePoint now) {
    if (now < next_reopen_) return;
    for (PwmChannel* channel : channels_) {
        if (!channel->open(config_.period_ns).ok) {
            backoff_ = std::min<TimePoint::duration>(backoff_ * 2, kLastBackoff);
            next_reopen_ = now + backoff_;
            return;
        }
    }
    ++reopens_;
    io_fault_ = false;
    applied_active_ = false;  // re-enable if active
    applied_ = clock_.now();   // commands from before the fault do not apply
    status_ = ptu::DriverStatus::success();
}

void PwmServo::publish() {
    reports_.try_publish([this](ServoReport& report) {
        report.servos = servos_;
        report.status = status_;
        report.enabled = enabled_;
        report.active = applied_active_;
        report.holding = holding_;
        report.reopens = reopens_;
    });
}

std::unique_ptr<PwmServo> make_pwm_servo_driver(const PwmSettings& settings, const Clock& clock, PwmChannel& pan,
                                                PwmChannel& tilt, std::string& error) {
    PwmConfig config;
    if (!make_pwm_config(settings, config, error)) return nullptr;
    return std::make_unique<PwmServo>(config, pan, tilt, clock);
}

std::unique_ptr<ptu::PtuDriver> make_pwm_servo_driver(const PwmSettings& settings, const Clock& clock,
                                                      std::string& error) {
    PwmConfig config;
    if (!make_pwm_config(settings, config, error)) return nullptr;
    std::array<std::unique_ptr<PwmChannel>, 2> channels{
        std::make_unique<SysfsPwmChannel>(settings.sysfs_root, settings.pan_chip, settings.pan_channel),
        std::make_unique<SysfsPwmChannel>(settings.sysfs_root, settings.tilt_chip, settings.tilt_channel)};
    PwmChannel& pan = *channels[0];
    PwmChannel& tilt = *channels[1];
    return std::make_unique<PwmServo>(config, pan, tilt, clock, std::move(channels));
}

}  // namespace rays::gpio
