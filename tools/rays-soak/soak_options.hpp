// SPDX-License-Identifier: Apache-2.0
// Command line of rays-soak.
#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rays::soak {

inline constexpr const char* kUsage =
    "usage: rays-soak [--frames N] [--scenario soak|soak-clutter|ramp|patrol|crowd|horizon] [--seed N | --seeds A-B]\n"
    "                 [--config FILE.ini] [--law predictive|proportional] [--method rays|snake]\n"
    "                 [--gain G | --sweep-gain G1,G2,... | --compare G1,G2,...]\n"
    "                 [--budget-ms B | --lockstep] [--json] [--plot FILE.png] [--trace FILE.csv]\n"
    "                 [--overlay DIR [--overlay-window FROM_S,TO_S]]";

struct SoakOptions {
    long frames = 45000;
    std::optional<std::string> scenario;  // overrides sim.scenario (raysd's default: soak)
    std::optional<int> seed;
    // --seeds A-B: one run per seed from A to B, each summarised, then their totals: a change to the
    // tracker moves single runs by more than it moves the scenario.
    std::optional<std::pair<int, int>> seeds;  // first, last
    std::string config_path;          // empty: raysd's built-in defaults
    std::optional<std::string> law;   // overrides control.law
    std::optional<std::string> method;  // overrides track.method
    std::optional<double> gain;       // overrides control.gain
    std::vector<double> sweep_gains;  // one run per gain
    // The speed comparison: the proportional law at each of these gains, then the predictive law and
    // the greedy snake (with the predictive law), all on the same config; the fastest targets side by side.
    std::vector<double> compare_gains;
    std::optional<double> budget_ms;  // overrides loop.budget_ms
    bool lockstep = false;  // time stands still within a frame: no budget, latency 0, reproducible
    bool json = false;
    std::string plot_path;
    std::string trace_path;           // one CSV row per frame
    std::string overlay_dir;          // PNG per frame: the view, the contour, the true centre
    double overlay_from_s = 0, overlay_to_s = 1e300;
    bool help = false;
};

// Fills `out` from the arguments; on a bad argument returns a one-line message.
std::optional<std::string> parse_options(int argc, const char* const* argv, SoakOptions& out);

}  // namespace rays::soak
