// SPDX-License-Identifier: Apache-2.0
// ptu-bench [--commands N] [--json] [NAME...]: runs the registered driver latency benches (all, or
// those named) and prints median, p99 and max command-to-bus latency per driver.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "latency_bench.hpp"

namespace rays::bench {
namespace {

std::map<std::string, LatencyBench>& registry() {
    static std::map<std::string, LatencyBench> benches;
    return benches;
}

double quantile(std::vector<double> sorted, double q) {
    return sorted[std::min(sorted.size() - 1, static_cast<std::size_t>(q * static_cast<double>(sorted.size())))];
}

}  // namespace

bool register_bench(LatencyBench bench) {
    std::string name = bench.name;
    return registry().emplace(std::move(name), std::move(bench)).second;
}

}  // namespace rays::bench

int main(int argc, char** argv) {
    using namespace rays::bench;
    int commands = 1000;
    bool as_json = false;
    std::vector<std::string> names;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "--commands" && i + 1 < argc) commands = std::atoi(argv[++i]);
        else if (arg == "--json") as_json = true;
        else if (arg == "--list") {
            for (const auto& [name, bench] : registry()) std::printf("%-14s %s\n", name.c_str(), bench.description.c_str());
            return 0;
        } else if (!arg.empty() && arg[0] == '-') {
            std::fprintf(stderr, "usage: ptu-bench [--commands N] [--json] [--list] [NAME...]\n");
            return 2;
        } else names.push_back(arg);
    }
    if (names.empty())
        for (const auto& [name, bench] : registry()) names.push_back(name);
    nlohmann::json rows = nlohmann::json::array();
    int failures = 0;
    if (!as_json) std::printf("%-14s %8s %10s %10s %10s\n", "driver", "commands", "median_us", "p99_us", "max_us");
    for (const std::string& name : names) {
        auto found = registry().find(name);
        if (found == registry().end()) {
            std::fprintf(stderr, "ptu-bench: no bench named %s (--list shows them)\n", name.c_str());
            return 2;
        }
        std::string error;
        std::vector<double> latencies = found->second.run(commands, error);
        if (latencies.empty()) {
            std::fprintf(stderr, "ptu-bench: %s: %s\n", name.c_str(), error.c_str());
            ++failures;
            continue;
        }
        std::sort(latencies.begin(), latencies.end());
        double median = quantile(latencies, 0.5), p99 = quantile(latencies, 0.99), max = latencies.back();
        const std::string note = found->second.note ? found->second.note() : "";
        rows.push_back({{"driver", name}, {"commands", latencies.size()}, {"median_us", median}, {"p99_us", p99},
                        {"max_us", max}, {"note", note}});
        if (!as_json) {
            std::printf("%-14s %8zu %10.1f %10.1f %10.1f\n", name.c_str(), latencies.size(), median, p99, max);
            if (!note.empty()) std::printf("  %s\n", note.c_str());
        }
    }
    if (as_json) std::printf("%s\n", nlohmann::json{{"rows", rows}}.dump().c_str());
    return failures == 0 ? 0 : 1;
}
