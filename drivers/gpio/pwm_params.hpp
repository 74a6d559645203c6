// SPDX-License-Identifier: Apache-2.0
// The [pwm] keys of raysd.ini (driver "pwm-servo"), one parameter table over PwmSettings.
#pragma once
#include "config/param_table.hpp"
#include "drivers/gpio/pwm_settings.hpp"

namespace rays::gpio {

const config::ParamTable<PwmSettings>& pwm_params();

}  // namespace rays::gpio
