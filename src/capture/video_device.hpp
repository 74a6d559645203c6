// SPDX-License-Identifier: Apache-2.0
// The seam between the camera and the kernel: the handful of calls V4L2 streaming needs, with the
// syscalls' own conventions (−1 and errno on failure), so tests can stand in for a driver.
#pragma once
#include <sys/types.h>

#include <cstddef>
#include <string>

namespace rays::capture {

class VideoDevice {
public:
    virtual ~VideoDevice() = default;

    virtual int open(const char* path, int flags) = 0;
    virtual int close(int fd) = 0;
    virtual int ioctl(int fd, unsigned long request, void* arg) = 0;
    virtual void* mmap(std::size_t length, int prot, int flags, int fd, off_t offset) = 0;  // MAP_FAILED + errno on failure
    virtual int munmap(void* address, std::size_t length) = 0;
    // Waits up to timeout_ms for fd to become readable. Returns the poll revents (POLLIN, POLLERR,
    // POLLHUP, ...), 0 on timeout, −1 with errno. With fd < 0 it only waits.
    virtual int poll(int fd, int timeout_ms) = 0;
};

// The real thing: open(2), close(2), ioctl(2), mmap(2), munmap(2), poll(2).
class SystemVideoDevice final : public VideoDevice {
public:
    int open(const char* path, int flags) override;
    int close(int fd) override;
    int ioctl(int fd, unsigned long request, void* arg) override;
    void* mmap(std::size_t length, int prot, int flags, int fd, off_t offset) override;
    int munmap(void* address, std::size_t length) override;
    int poll(int fd, int timeout_ms) override;
};

// ioctl, repeated while a signal interrupts it.
int ioctl_retrying(VideoDevice& device, int fd, unsigned long request, void* arg);

// "ENODEV", "EIO", ... ("errno 1234" for a number glibc does not name).
std::string errno_name(int error);

// A step that failed: the errno it failed with (0 when no call failed) and one line saying what.
struct DeviceError {
    int code = 0;
    std::string message;
};

// From errno just after a failed call: "what: ENODEV".
DeviceError call_failed(const std::string& what);

}  // namespace rays::capture
