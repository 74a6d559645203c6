// SPDX-License-Identifier: Apache-2.0
#include "drivers/can/socket_can_transport.hpp"

#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <thread>

namespace rays::can {

SocketCanTransport::SocketCanTransport(std::string interface_name)
    : interface_(std::move(interface_name)), wake_fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {}

SocketCanTransport::~SocketCanTransport() {
    close();
    if (wake_fd_ >= 0) ::close(wake_fd_);
}

void SocketCanTransport::note_error(const char* what, int error_number) {
    std::snprintf(error_, sizeof error_, "%s: %s: %s", interface_.c_str(), what, std::strerror(error_number));
}

bool SocketCanTransport::open(std::string& error) {
    close();
    if (interface_.empty() || interface_.size() >= IFNAMSIZ) {
        error = "CAN interface name '" + interface_ + "' is empty or too long";
        return false;
    }
    socket_ = ::socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK | SOCK_CLOEXEC, CAN_RAW);
    if (socket_ < 0) {
        note_error("socket(PF_CAN, SOCK_RAW, CAN_RAW)", errno);
        error = error_;
        return false;
    }
    // Error frames: bus-off, controller problems (queue overflows, error passive) and restarts.
    const can_err_mask_t mask = CAN_ERR_BUSOFF | CAN_ERR_CRTL | CAN_ERR_RESTARTED;
    ::setsockopt(socket_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &mask, sizeof mask);
    const unsigned index = ::if_nametoindex(interface_.c_str());
    sockaddr_can address{};
    address.can_family = AF_CAN;
    address.can_ifindex = static_cast<int>(index);
    if (index == 0 || ::bind(socket_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
        note_error(index == 0 ? "no such interface" : "bind", errno);
        error = error_;
        close();
        return false;
    }
    return true;
}

void SocketCanTransport::close() {
    if (socket_ >= 0) ::close(socket_);
    socket_ = -1;
}

CanIo SocketCanTransport::send(const can_frame& frame) {
    if (socket_ < 0) return CanIo::Down;
    auto pause = std::chrono::microseconds(100);
    for (int attempt = 0;; ++attempt) {
        if (::write(socket_, &frame, sizeof frame) == static_cast<ssize_t>(sizeof frame)) {
            ++sent_;
            return CanIo::Ok;
        }
        const int error_number = errno;
        if (error_number != ENOBUFS && error_number != EAGAIN) {
            note_error("write", error_number);
            return CanIo::Down;
        }
        if (attempt == kSendRetries) {
            ++dropped_;
            return CanIo::Busy;
        }
        ++retries_;
        std::this_thread::sleep_for(pause);  // the I/O thread's pause; the frame loop never sends
        pause *= 2;
    }
}

CanIo SocketCanTransport::receive(can_frame& frame, std::chrono::microseconds timeout) {
    if (socket_ < 0) return CanIo::Down;
    for (;;) {
        const ssize_t got = ::read(socket_, &frame, sizeof frame);
        if (got == static_cast<ssize_t>(sizeof frame)) {
            ++received_;
            return CanIo::Ok;
        }
        if (got < 0 && errno != EAGAIN && errno != EINTR) {
            note_error("read", errno);
            return CanIo::Down;
        }
        pollfd fds[2] = {{socket_, POLLIN, 0}, {wake_fd_, POLLIN, 0}};
        const int ready = ::poll(fds, 2, static_cast<int>((timeout.count() + 999) / 1000));
        if (ready == 0) return CanIo::Timeout;
        if (ready < 0 && errno != EINTR) {
            note_error("poll", errno);
            return CanIo::Down;
        }
        if ((fds[1].revents & POLLIN) != 0) {
            std::uint64_t count = 0;
            if (::read(wake_fd_, &count, sizeof count) < 0) count = 0;
            return CanIo::Woken;
        }
        if ((fds[0].revents & (POLLERR | POLLHUP | POLLNVAL)) != 0) {
            note_error("poll", ENETDOWN);
            return CanIo::Down;
        }
    }
}

void SocketCanTransport::wake() {
    if (wake_fd_ < 0) return;
    const std::uint64_t one = 1;
    if (::write(wake_fd_, &one, sizeof one) < 0) return;  // counter full: a wake is pending anyway
}

CanCounters SocketCanTransport::counters() const { return {sent_, received_, retries_, dropped_}; }

}  // namespace rays::can
