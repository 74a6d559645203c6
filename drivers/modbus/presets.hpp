// SPDX-License-Identifier: Apache-2.0
// Named register maps of real drive families (presets.cpp cites each manual).
#pragma once
#include <optional>
#include <string>

#include "drivers/modbus/register_map.hpp"

namespace rays::ptu {

struct Preset {
    std::string name;
    RegisterMap map;  // slaves are the family's defaults; scales are the settings'
};

std::optional<Preset> find_preset(const std::string& name);

}  // namespace rays::ptu
