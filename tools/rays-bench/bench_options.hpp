// SPDX-License-Identifier: Apache-2.0
// Command line of rays-bench.
#pragma once
#include <optional>
#include <string>

namespace rays::bench {

inline constexpr const char* kUsage =
    "usage: rays-bench [--scene NAME] [--frames N] [--config FILE.ini] [--json] [--hypotheses K]";

struct BenchOptions {
    std::string scene = "clutter";
    int frames = 300;
    std::string config_path;  // empty: the built-in defaults
    bool json = false;
    std::optional<int> hypotheses;  // overrides rays.hypotheses (K)
    bool help = false;
};

// Fills `out` from the arguments; on a bad argument returns a one-line message.
std::optional<std::string> parse_options(int argc, const char* const* argv, BenchOptions& out);

}  // namespace rays::bench
