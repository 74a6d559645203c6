// SPDX-License-Identifier: Apache-2.0
// The one interface every pan/tilt unit driver implements (mock, Modbus, CANopen, ODrive, GPIO),
// with a lifecycle as ros2_control's hardware interfaces: configure → activate → (write/read)* →
// deactivate. Units: radians and rad/s; pan positive to the right, tilt positive up.
//
// write() and read() are called from the real-time frame loop once per frame: they must not block,
// allocate or throw. A driver whose bus is slow (libmodbus is synchronous) runs its own I/O thread
// and exchanges the newest command and the newest state with it through fixed mailboxes.
// Limits are not a driver's business: PtuLimiter (ptu_limiter.hpp) enforces them above every driver.
#pragma once
#include <array>
#include <cstddef>

#include "core/clock.hpp"

namespace rays::ptu {

enum class Axis { Pan = 0, Tilt = 1 };
constexpr std::size_t kAxes = 2;

enum class CommandMode { Velocity, Position };

struct AxisCommand {
    CommandMode mode = CommandMode::Velocity;
    double value = 0.0;  // rad/s in Velocity mode, rad in Position mode
};

struct PtuCommand {
    std::array<AxisCommand, kAxes> axes{};
    static PtuCommand stop() { return {}; }  // zero velocity on both axes
};

struct AxisState {
    double position_rad = 0.0;
    double velocity_rad_s = 0.0;
    bool enabled = false;
    bool fault = false;
    bool homed = false;
};

struct PtuState {
    std::array<AxisState, kAxes> axes{};
    TimePoint stamp{};  // when the unit reported this state (monotonic)
};

// A driver's error as a value: ok, or a fixed-size message (no allocation in the frame path).
struct DriverStatus {
    bool ok = true;
    std::array<char, 120> message{};  // NUL-terminated, empty when ok

    static DriverStatus success() { return {}; }
    static DriverStatus failure(const char* text);
    const char* what() const { return message.data(); }
};

class PtuDriver {
public:
    virtual ~PtuDriver() = default;

    virtual const char* name() const = 0;
    // How long after write() the unit acts on a command (s); PtuLimiter predicts across it.
    virtual double command_latency_s() const { return 0.0; }

    // Opens the connection and checks the unit answers; no motion. May block and allocate.
    virtual DriverStatus configure() = 0;
    // Enables the axes so that commands move them. May block.
    virtual DriverStatus activate() = 0;
    // Stops both axes and disables them; always safe to call, also after a failure. May block.
    virtual void deactivate() = 0;

    // Starts homing both axes (a unit with limit switches or an index finds its zero; afterwards
    // AxisState::homed is true). Non-blocking; progress shows in read(). Units that know their
    // absolute position report homed from the start and succeed at once.
    virtual DriverStatus home(TimePoint now) {
        (void)now;
        return DriverStatus::failure("this unit cannot home");
    }

    // Cyclic, from the frame loop: hands over the newest command. Non-blocking.
    virtual DriverStatus write(const PtuCommand& command, TimePoint now) = 0;
    // Cyclic, from the frame loop: the newest state the unit reported. Non-blocking.
    virtual DriverStatus read(PtuState& state, TimePoint now) = 0;
};

}  // namespace rays::ptu
