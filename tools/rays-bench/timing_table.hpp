// SPDX-License-Identifier: Apache-2.0
// Table 2 of the paper: time to process one frame for different ray spacings Δφ.
#pragma once
#include <vector>

#include "bench_setup.hpp"

namespace rays::bench {

struct TimingRow {
    double dphi = 0;         // rad
    int rays = 0;            // 2π / Δφ
    double paper_ms = 0;     // the paper's HP 735/99 figure for this Δφ
    int frames = 0;          // tracking frames measured (after the warm-up)
    double median_us = 0;
    double p99_us = 0;
    double max_us = 0;
    double fps = 0;          // 1e6 / median
};

// Runs a fresh tracker with a far deadline for each Δφ in {π/180, π/36, π/18, π/9} and times every
// frame's Tracker::process() with the steady clock; only tracking frames count, the first
// kWarmupFrames of them excepted.
std::vector<TimingRow> measure_timing_table(const BenchSetup& setup);

inline constexpr int kWarmupFrames = 5;

}  // namespace rays::bench
