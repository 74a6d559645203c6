// SPDX-License-Identifier: Apache-2.0
// The frame loop's real-time options: SCHED_FIFO priority, CPU affinity and mlockall. Each returns
// what became of the request as one line for the log and `status` ("SCHED_FIFO 40", "refused:
// Operation not permitted", "not requested"); a refusal is reported, never silently ignored.
#pragma once
#include <string>

namespace rays::daemon {

struct RealtimeReport {
    std::string text;
    bool refused = false;
};

// On the calling thread. priority 0: not requested.
RealtimeReport set_fifo_priority(int priority);
// On the calling thread. cpu < 0: not requested.
RealtimeReport pin_to_cpu(int cpu);
// The whole process.
RealtimeReport lock_memory(bool requested);

}  // namespace rays::daemon
