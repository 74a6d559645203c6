// SPDX-License-Identifier: Apache-2.0
// Per-axis inversion and zero offset, once above every driver: the daemon works in rig angles (pan
// positive to the right, tilt positive up, zero straight ahead); the unit in its own. For each axis
//     unit angle = sign · rig angle + zero,   sign = -1 when inverted,
// and velocities scale by sign. Wraps a driver and is itself one; the limiter sits above it, so soft
// limits are in rig angles.
#pragma once
#include <array>

#include "drivers/ptu_driver.hpp"

namespace rays::ptu {

struct AxisCalibration {
    bool inverted = false;
    double zero_rad = 0.0;  // the unit's angle where the rig's angle is 0
};

class CalibratedPtu final : public PtuDriver {
public:
    CalibratedPtu(PtuDriver& unit, const std::array<AxisCalibration, kAxes>& axes) : unit_(unit), axes_(axes) {}

    const char* name() const override { return unit_.name(); }
    double command_latency_s() const override { return unit_.command_latency_s(); }
    DriverStatus configure() override { return unit_.configure(); }
    DriverStatus activate() override { return unit_.activate(); }
    void deactivate() override { unit_.deactivate(); }
    DriverStatus home(TimePoint now) override { return unit_.home(now); }
    DriverStatus write(const PtuCommand& command, TimePoint now) override;
    DriverStatus read(PtuState& state, TimePoint now) override;

private:
    PtuDriver& unit_;
    std::array<AxisCalibration, kAxes> axes_;
};

}  // namespace rays::ptu
