// SPDX-License-Identifier: Apache-2.0
// rays-bench: the paper's Table 2 (time per frame against Δφ) and the any-time curve, measured on
// this machine over a generated scene.
#include <cstdio>

#include "bench_options.hpp"
#include "bench_report.hpp"
#include "bench_setup.hpp"

int main(int argc, char** argv) {
    using namespace rays::bench;
    BenchOptions options;
    if (const auto error = parse_options(argc, argv, options)) {
        std::fprintf(stderr, "rays-bench: %s (%s)\n", error->c_str(), kUsage);
        return 2;
    }
    if (options.help) {
        std::printf("%s\n", kUsage);
        return 0;
    }
    BenchSetup setup;
    if (const auto error = make_setup(options, setup)) {
        std::fprintf(stderr, "rays-bench: %s\n", error->c_str());
        return 2;
    }
    const std::vector<TimingRow> rows = measure_timing_table(setup);
    const std::vector<AnytimePoint> curve = measure_anytime_curve(setup);
    if (options.json)
        std::printf("%s\n", report_json(setup, rows, curve).dump().c_str());
    else
        print_report(stdout, setup, rows, curve);
    return 0;
}
