// SPDX-License-Identifier: Apache-2.0
// raysctl's output: the reply line itself with --json, else a short human-readable form.
#pragma once
#include <nlohmann/json.hpp>

namespace rays::ctl {

void print_reply(const nlohmann::json& reply, bool as_json);

}  // namespace rays::ctl
