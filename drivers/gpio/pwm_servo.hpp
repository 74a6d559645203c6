// SPDX-License-Identifier: Apache-2.0
// Driver "pwm-servo": two RC hobby servos on hardware PWM ([pwm] in raysd.ini). Software cannot hold
// a servo pulse steady; the PWM hardware makes the pulses, the driver only writes duty_cycle.
// Position commands set the angle (clamped to the configured range); velocity commands are integrated
// from the estimated angle into the angle commanded next, so zero velocity (stop) holds the servo
// where it is estimated to be. An I/O thread does every file write: it applies the newest command,
// holds the estimated position when commands go stale, reopens a failed channel with backoff.
// read() reports the estimate (a servo gives no feedback); both axes count as homed (absolute).
#pragma once
#include <array>
#include <atomic>
#include <memory>
#include <string>
#include <thread>

#include "common/latest_value.hpp"
#include "drivers/gpio/pwm_channel.hpp"
#include "drivers/gpio/pwm_settings.hpp"
#include "drivers/gpio/servo_model.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::gpio {

struct PwmConfig {
    std::array<ServoRange, ptu::kAxes> ranges{};
    std::array<double, ptu::kAxes> start_rad{};
    long period_ns = 20000000;
    bool disable_on_deactivate = false;
    double command_timeout_s = 0.5;
    double move_speed_rad_s = 1.5708;  // a position command's slew
};

bool make_pwm_config(const PwmSettings& settings, PwmConfig& config, std::string& error);

struct ServoSlot {
    std::array<double, ptu::kAxes> target_rad{};
    TimePoint written{};  // on the driver's Clock
    bool valid = false;
};

struct ServoReport {
    std::array<ServoModel, ptu::kAxes> servos{ServoModel(ServoRange{}, 0.0, TimePoint{}),
                                              ServoModel(ServoRange{}, 0.0, TimePoint{})};
    ptu::DriverStatus status;
    bool enabled = false;  // the outputs are on
    bool active = false;   // the I/O thread has applied the last activate/deactivate
    bool holding = false;  // commands went stale: holding the estimated position
    long reopens = 0;
};

class PwmServo final : public ptu::PtuDriver {
public:
    static constexpr std::chrono::milliseconds kPeriod{1};  // I/O thread wake-up
    static constexpr std::chrono::milliseconds kFirstBackoff{500};
    static constexpr std::chrono::seconds kLastBackoff{8};

    // The channels must outlive the driver; `owned` may hold them.
    PwmServo(const PwmConfig& config, PwmChannel& pan, PwmChannel& tilt, const Clock& clock,
             std::array<std::unique_ptr<PwmChannel>, 2> owned = {});
    ~PwmServo() override;

    const char* name() const override { return "pwm-servo"; }
    double command_latency_s() const override;
    ptu::DriverStatus configure() override;
    ptu::DriverStatus activate() override;
    void deactivate() override;
    ptu::DriverStatus home(TimePoint now) override;
    ptu::DriverStatus write(const ptu::PtuCommand& command, TimePoint now) override;
    ptu::DriverStatus read(ptu::PtuState& state, TimePoint now) override;

    ServoReport report() const;  // waits for the lock: not for the frame loop

private:
    void run();
    bool apply(const ServoSlot& slot, TimePoint now, TimePoint clock_now);
    bool set_duty(std::size_t axis, long duty_ns);
    bool set_enabled(bool enabled);
    void io_failed(TimePoint now, const char* what);
    void reopen(TimePoint now);
    void publish();

    PwmConfig config_;
    std::array<std::unique_ptr<PwmChannel>, 2> owned_;
    std::array<PwmChannel*, ptu::kAxes> channels_;
    const Clock& clock_;
    LatestValue<ServoSlot> commands_;
    LatestValue<ServoReport> reports_;
    std::atomic<bool> active_{false};
    std::atomic<bool> quit_{false};
    std::thread thread_;
    bool configured_ = false;

    // Frame-thread state.
    ServoReport last_;
    TimePoint last_write_{};
    bool written_ = false;

    // I/O-thread state.
    std::array<ServoModel, ptu::kAxes> servos_;
    std::array<long, ptu::kAxes> duty_{-1, -1};
    ServoSlot slot_;
    TimePoint applied_{};  // written time of the last slot applied
    bool enabled_ = false;
    bool applied_active_ = false;
    bool holding_ = false;
    bool io_fault_ = false;
    ptu::DriverStatus status_;
    TimePoint next_reopen_{};
    TimePoint::duration backoff_ = kFirstBackoff;
    long reopens_ = 0;
};

std::unique_ptr<ptu::PtuDriver> make_pwm_servo_driver(const PwmSettings& settings, const Clock& clock,
                                                      std::string& error);
std::unique_ptr<PwmServo> make_pwm_servo_driver(const PwmSettings& settings, const Clock& clock, PwmChannel& pan,
                                                PwmChannel& tilt, std::string& error);

}  // namespace rays::gpio
