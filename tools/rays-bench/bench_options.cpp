// SPDX-License-Identifier: Apache-2.0
#include "bench_options.hpp"

#include <charconv>
#include <string_view>

namespace rays::bench {
namespace {

std::optional<int> positive_int(std::string_view text) {
    int value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc{} || end != text.data() + text.size() || value <= 0) return std::nullopt;
    return value;
}

}  // namespace

std::optional<std::string> parse_options(int argc, const char* const* argv, BenchOptions& out) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--json") {
            out.json = true;
            continue;
        }
        if (arg == "--help" || arg == "-h") {
            out.help = true;
            continue;
        }
        if (arg != "--scene" && arg != "--frames" && arg != "--config" && arg != "--hypotheses")
            return "unknown argument '" + std::string(arg) + "'";
        if (i + 1 == argc) return std::string(arg) + " needs a value";
        const std::string_view value = argv[++i];
        if (arg == "--scene") {
            out.scene = value;
        } else if (arg == "--config") {
            out.config_path = value;
        } else {
            const std::optional<int> n = positive_int(value);
            if (!n) return std::string(arg) + " needs a positive integer, not '" + std::string(value) + "'";
            if (arg == "--frames") out.frames = *n;
            else out.hypotheses = *n;
        }
    }
    return std::nullopt;
}

}  // namespace rays::bench
