// SPDX-License-Identifier: Apache-2.0
// The [gpio] keys of raysd.ini (driver "gpio-stepper"), one parameter table over GpioSettings.
#pragma once
#include "config/param_table.hpp"
#include "drivers/gpio/gpio_settings.hpp"

namespace rays::gpio {

const config::ParamTable<GpioSettings>& gpio_params();

}  // namespace rays::gpio
