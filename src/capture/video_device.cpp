// SPDX-License-Identifier: Apache-2.0
#include "capture/video_device.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace rays::capture {

int SystemVideoDevice::open(const char* path, int flags) { return ::open(path, flags); }

int SystemVideoDevice::close(int fd) { return ::close(fd); }

int SystemVideoDevice::ioctl(int fd, unsigned long request, void* arg) { return ::ioctl(fd, request, arg); }

void* SystemVideoDevice::mmap(std::size_t length, int prot, int flags, int fd, off_t offset) {
    return ::mmap(nullptr, length, prot, flags, fd, offset);
}

int SystemVideoDevice::munmap(void* address, std::size_t length) { return ::munmap(address, length); }

// poll(2) ignores a negative fd, so with fd < 0 this is a plain wait.
int SystemVideoDevice::poll(int fd, int timeout_ms) {
    pollfd p{fd, POLLIN, 0};
    const int n = ::poll(&p, 1, timeout_ms);
    return n > 0 ? p.revents : n;
}

int ioctl_retrying(VideoDevice& device, int fd, unsigned long request, void* arg) {
    int result;
    do result = device.ioctl(fd, request, arg);
    while (result == -1 && errno == EINTR);
    return result;
}

std::string errno_name(int error) {
    if (const char* name = strerrorname_np(error)) return name;
    return "errno " + std::to_string(error);
}

DeviceError call_failed(const std::string& what) {
    const int code = errno;
    return DeviceError{code, what + ": " + errno_name(code)};
}

}  // namespace rays::capture
