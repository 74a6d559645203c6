// SPDX-License-Identifier: Apache-2.0
#include "timing_table.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include "core/tracker.hpp"

namespace rays::bench {
namespace {

struct PaperRow {
    int pi_divisor;   // Δφ = π / pi_divisor
    double paper_ms;  // Table 2, HP 735/99
};
constexpr PaperRow kPaperRows[] = {{180, 38}, {36, 19}, {18, 12}, {9, 9}};

// Nearest-rank quantile of sorted samples.
double quantile(const std::vector<double>& sorted, double q) {
    const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(sorted.size())));
    return sorted[std::clamp<std::size_t>(rank, 1, sorted.size()) - 1];
}

TimingRow measure_row(const BenchSetup& setup, PaperRow paper) {
    TimingRow row;
    row.rays = 2 * paper.pi_divisor;
    row.dphi = std::numbers::pi / paper.pi_divisor;
    row.paper_ms = paper.paper_ms;

    const SteadyClock clock;
    Tracker tracker(with_ray_count(setup.config, row.rays), clock);
    tracker.start_at(setup.start);
    std::vector<double> samples_us;
    samples_us.reserve(setup.images.size());
    int tracking = 0;
    for (const GreyImage& image : setup.images) {
        const TimePoint start = MonoClock::now();
        const FrameResult& result = tracker.process(image, start + std::chrono::hours(1));
        const TimePoint end = MonoClock::now();
        if (result.state != TrackState::Tracking || ++tracking <= kWarmupFrames) continue;
        samples_us.push_back(std::chrono::duration<double, std::micro>(end - start).count());
    }
    row.frames = static_cast<int>(samples_us.size());
    if (samples_us.empty()) return row;
    std::sort(samples_us.begin(), samples_us.end());
    row.median_us = quantile(samples_us, 0.5);
    row.p99_us = quantile(samples_us, 0.99);
    row.max_us = samples_us.back();
    row.fps = 1e6 / row.median_us;
    return row;
}

}  // namespace

std::vector<TimingRow> measure_timing_table(const BenchSetup& setup) {
    std::vector<TimingRow> rows;
    for (const PaperRow& paper : kPaperRows) rows.push_back(measure_row(setup, paper));
    return rows;
}

}  // namespace rays::bench
