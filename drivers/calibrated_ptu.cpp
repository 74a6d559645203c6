// SPDX-License-Identifier: Apache-2.0
#include "drivers/calibrated_ptu.hpp"

namespace rays::ptu {

DriverStatus CalibratedPtu::write(const PtuCommand& command, TimePoint now) {
    PtuCommand unit_command = command;
    for (std::size_t i = 0; i < kAxes; ++i) {
        const double sign = axes_[i].inverted ? -1.0 : 1.0;
        AxisCommand& axis = unit_command.axes[i];
        axis.value = axis.mode == CommandMode::Position ? sign * axis.value + axes_[i].zero_rad : sign * axis.value;
    }
    return unit_.write(unit_command, now);
}

DriverStatus CalibratedPtu::read(PtuState& state, TimePoint now) {
    const DriverStatus status = unit_.read(state, now);
    for (std::size_t i = 0; i < kAxes; ++i) {
        const double sign = axes_[i].inverted ? -1.0 : 1.0;
        AxisState& axis = state.axes[i];
        axis.position_rad = sign * (axis.position_rad - axes_[i].zero_rad);
        axis.velocity_rad_s = sign * axis.velocity_rad_s;
    }
    return status;
}

}  // namespace rays::ptu
