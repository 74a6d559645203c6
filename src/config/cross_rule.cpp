// SPDX-License-Identifier: Apache-2.0
#include "config/cross_rule.hpp"

#include "config/param_text.hpp"

namespace rays::config {
namespace {

CrossRule ordered(std::string lower, std::string upper, bool strict) {
    CrossRule rule;
    rule.keys = {lower, upper};
    rule.check = [lower, upper, strict](const ParamLookup& value) -> std::optional<std::string> {
        double low = value(lower);
        double high = value(upper);
        if (strict ? low < high : low <= high) return std::nullopt;
        return lower + " = " + format_number(low) + (strict ? " must be < " : " must be <= ") + upper + " = " +
               format_number(high);
    };
    return rule;
}

}  // namespace

CrossRule at_most(std::string lower, std::string upper) {
    return ordered(std::move(lower), std::move(upper), false);
}

CrossRule less_than(std::string lower, std::string upper) {
    return ordered(std::move(lower), std::move(upper), true);
}

}  // namespace rays::config
