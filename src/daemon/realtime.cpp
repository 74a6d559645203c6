// SPDX-License-Identifier: Apache-2.0
#include "daemon/realtime.hpp"

#include <pthread.h>
#include <sched.h>
#include <sys/mman.h>

#include <cerrno>
#include <cstring>

namespace rays::daemon {
namespace {

RealtimeReport refused(const std::string& what, int error) { return {"refused: " + what + ": " + std::strerror(error), true}; }

}  // namespace

RealtimeReport set_fifo_priority(int priority) {
    if (priority <= 0) return {"not requested", false};
    sched_param param{};
    param.sched_priority = priority;
    if (int error = pthread_setschedparam(pthread_self(), SCHED_FIFO, &param); error != 0)
        return refused("SCHED_FIFO " + std::to_string(priority), error);
    return {"SCHED_FIFO " + std::to_string(priority), false};
}

RealtimeReport pin_to_cpu(int cpu) {
    if (cpu < 0) return {"not requested", false};
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(static_cast<std::size_t>(cpu), &set);
    if (int error = pthread_setaffinity_np(pthread_self(), sizeof set, &set); error != 0)
        return refused("CPU " + std::to_string(cpu), error);
    return {"pinned to CPU " + std::to_string(cpu), false};
}

RealtimeReport lock_memory(bool requested) {
    if (!requested) return {"not requested", false};
    if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) return refused("mlockall", errno);
    return {"locked (mlockall)", false};
}

}  // namespace rays::daemon
