// SPDX-License-Identifier: Apache-2.0
// Register maps of drive families as their manufacturers publish them. Only what the cited manual
// shows is filled in; what could not be verified is left absent (-1) and said so, never guessed.
#include "drivers/modbus/presets.hpp"

#include <cstring>

namespace rays::ptu {
namespace {

// Leadshine ELD2 / ELD2-RS low-voltage servo (single axis per drive; pan and tilt are two slaves,
// default ids 1 and 2). Source: Leadshine "User Manual for ELD2 Servo", Modbus chapter, PR motion
// over RS-485: one FC 0x10 write to 0x6200..0x6207 = Pr9.00 mode, Pr9.01/Pr9.02 position high/low,
// Pr9.03 speed (rpm), Pr9.04 acc, Pr9.05 dec, Pr9.06 delay, Pr9.07 trigger (0x10 starts PR0).
// Velocity mode of a PR path is mode 0x0002 (absolute position 0x0001). Used here: mode 0x6200 = 2
// once, then speed 0x6203 (16 bit, rpm) followed by trigger 0x6207 = 0x10.
// NOT verified against the manual, so absent: the actual-position and status (fault) registers,
// a servo-enable register (the drive enables through its SON input / Pr settings) and a
// communication-timeout register: with this preset the driver-side command timeout is the only
// watchdog and positions read as unknown (0).
Preset leadshine_eld2() {
    Preset preset;
    preset.name = "leadshine-eld2";
    for (std::size_t i = 0; i < kAxes; ++i) {
        AxisRegisters& axis = preset.map.axes[i];
        axis.slave = static_cast<int>(i) + 1;
        axis.mode = 0x6200;
        axis.mode_value = 0x0002;
        axis.velocity = 0x6203;
        axis.trigger = 0x6207;
        axis.trigger_value = 0x0010;
        axis.velocity_bits = 16;
    }
    return preset;
}

// UUMOTOR SVD48V dual-channel servo controller: pan on motor M1, tilt on M2 of one slave (default
// id 1). Source: "SVD48V Series hub motor servo controller user manual" V2.0, section 5.6.2 (M2
// motor control parameters: 0x5301 control command 0 stop / 1 start / 2 clear alarm, 0x5305 given
// speed int16 rpm, 0x530E given position int32) and 5.7.1 (M1 status: 0x5400 running status,
// 0x5410 speed, 0x5418 absolute position int32); section 4.1: multi-byte data low part first.
// Inferred by the manual's symmetry, NOT read in it: M1's control block at 0x5201/0x5205/0x520E and
// M2's status block at 0x5500/0x5518. No fault bit (0x5400 is only stop/running) and no
// communication-timeout register were found: the driver-side timeout is the only watchdog.
Preset uumotor_svd48v() {
    Preset preset;
    preset.name = "uumotor-svd48v";
    const int control[kAxes] = {0x5201, 0x5301};
    const int status[kAxes] = {0x5400, 0x5500};
    for (std::size_t i = 0; i < kAxes; ++i) {
        AxisRegisters& axis = preset.map.axes[i];
        axis.slave = 1;
        axis.enable = control[i];
        axis.enable_value = 1;
        axis.disable_value = 0;
        axis.velocity = control[i] + 4;
        axis.status = status[i];
        axis.actual_position = status[i] + 0x18;
        axis.velocity_bits = 16;
        axis.position_bits = 32;
        axis.low_word_first = true;
    }
    return preset;
}

}  // namespace

std::optional<Preset> find_preset(const std::string& name) {
    if (name == "leadshine-eld2") return leadshine_eld2();
    if (name == "uumotor-svd48v") return uumotor_svd48v();
    return std::nullopt;
}

}  // namespace rays::ptu
