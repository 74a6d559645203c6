// SPDX-License-Identifier: Apache-2.0
// Degrees, as users write them in raysd.ini and raysctl, and radians, as the code computes.
#pragma once
#include <numbers>

namespace rays {

inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;
inline constexpr double kDegPerRad = 180.0 / std::numbers::pi;

}  // namespace rays
