// SPDX-License-Identifier: Apache-2.0
// ptu-bench: command-to-bus latency per driver. Each driver's file registers one bench that writes
// `commands` commands through the real driver against a peer (the PTU simulator, an in-process drive
// simulator or a line-level seam) and returns, per command, the time from PtuDriver::write() to the
// moment the peer saw it on the bus.
#pragma once
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace rays::bench {

struct LatencyBench {
    std::string name;         // "modbus-tcp", "canopen", ...
    std::string description;  // what the peer is and where the time is taken
    // Latencies in microseconds, one per command; an empty result with `error` set on failure.
    std::function<std::vector<double>(int commands, std::string& error)> run;
    std::function<std::string()> note = nullptr;  // further figures of the last run, printed under its row
};

// Called from a static object in each bench file.
bool register_bench(LatencyBench bench);

}  // namespace rays::bench
