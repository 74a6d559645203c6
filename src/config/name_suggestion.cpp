// SPDX-License-Identifier: Apache-2.0
#include "config/name_suggestion.hpp"

#include <algorithm>

namespace rays::config {

int edit_distance(std::string_view a, std::string_view b) {
    const std::size_t columns = b.size() + 1;
    // Rows i-2, i-1 and i of the dynamic-programming table.
    std::vector<int> before(columns), previous(columns), current(columns);
    for (std::size_t j = 0; j < columns; ++j) previous[j] = static_cast<int>(j);
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = static_cast<int>(i);
        for (std::size_t j = 1; j < columns; ++j) {
            int substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string_view> closest_name(std::string_view name, const std::vector<std::string_view>& candidates,
                                             int max_distance) {
    std::optional<std::string_view> best;
    int best_distance = max_distance + 1;
    for (std::string_view candidate : candidates) {
        int distance = edit_distance(name, candidate);
        if (distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    return best;
}

}  // namespace rays::config
