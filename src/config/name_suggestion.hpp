// SPDX-License-Identifier: Apache-2.0
// "Did you mean ...?" for misspelt section and key names.
#pragma once
#include <optional>
#include <string_view>
#include <vector>

namespace rays::config {

// Edit distance counting insertions, deletions, substitutions and swaps of neighbours
// (optimal string alignment), so "alpah" is 1 away from "alpha".
int edit_distance(std::string_view a, std::string_view b);

// The candidate closest to `name` if it is at most `max_distance` edits away; the first on ties.
std::optional<std::string_view> closest_name(std::string_view name, const std::vector<std::string_view>& candidates,
                                             int max_distance = 2);

}  // namespace rays::config
