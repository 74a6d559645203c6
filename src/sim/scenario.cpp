// SPDX-License-Identifier: Apache-2.0
#include "sim/scenario.hpp"

#include <cmath>
#include <numbers>

namespace rays::sim {

bool Presence::at(double t_s) const {
    if (period_s <= 0) return true;
    const double local = t_s - period_s * std::floor(t_s / period_s);
    return local >= from_s && local < until_s;
}

double Exposure::gain(double t_s) const {
    const double drifted = 1.0 + drift * std::sin(2.0 * std::numbers::pi * t_s / drift_period_s);
    if (step_period_s <= 0) return drifted;
    const double local = t_s - step_period_s * std::floor(t_s / step_period_s);
    return local < step_period_s / 2 ? drifted : drifted * step_factor;
}

}  // namespace rays::sim
