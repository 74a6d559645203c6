// SPDX-License-Identifier: Apache-2.0
// rays-bench output: a human-readable table, or one JSON object.
#pragma once
#include <cstdio>
#include <nlohmann/json.hpp>
#include <vector>

#include "anytime_curve.hpp"
#include "bench_setup.hpp"
#include "timing_table.hpp"

namespace rays::bench {

void print_report(std::FILE* out, const BenchSetup& setup, const std::vector<TimingRow>& rows,
                  const std::vector<AnytimePoint>& curve);

// {"config":{...},"rows":[...],"anytime":[...]}
nlohmann::ordered_json report_json(const BenchSetup& setup, const std::vector<TimingRow>& rows,
                           const std::vector<AnytimePoint>& curve);

}  // namespace rays::bench
