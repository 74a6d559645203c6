// SPDX-License-Identifier: Apache-2.0
#include "daemon/loop_channels.hpp"

#include <sys/eventfd.h>
#include <unistd.h>

#include <cstdint>

namespace rays::daemon {

LoopChannels::LoopChannels(int queue_frames)
    : frames(queue_frames), wake_fd(eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {}

LoopChannels::~LoopChannels() {
    if (wake_fd >= 0) close(wake_fd);
}

void LoopChannels::wake_socket_thread() {
    std::uint64_t one = 1;
    [[maybe_unused]] ssize_t written = write(wake_fd, &one, sizeof one);  // EAGAIN: already pending
}

void LoopChannels::clear_wake() {
    std::uint64_t count = 0;
    [[maybe_unused]] ssize_t got = read(wake_fd, &count, sizeof count);
}

}  // namespace rays::daemon
