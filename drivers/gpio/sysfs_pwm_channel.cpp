// SPDX-License-Identifier: Apache-2.0
#include "drivers/gpio/sysfs_pwm_channel.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <thread>

namespace rays::gpio {
namespace {

// One value per write(), newline-terminated, as sysfs attributes take it.
bool write_value(int fd, long value) {
    char text[24];
    const int length = std::snprintf(text, sizeof text, "%ld\n", value);
    return pwrite(fd, text, static_cast<std::size_t>(length), 0) == length;
}

bool write_file(const std::string& path, long value) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return false;
    const bool ok = write_value(fd, value);
    ::close(fd);
    return ok;
}

ptu::DriverStatus failure(const char* what, const std::string& path) {
    char text[120];
    std::snprintf(text, sizeof text, "pwm: %s %s: %s", what, path.c_str(), std::strerror(errno));
    return ptu::DriverStatus::failure(text);
}

}  // namespace

SysfsPwmChannel::SysfsPwmChannel(std::string root, int chip, int channel)
    : chip_dir_(root + "/pwmchip" + std::to_string(chip)),
      channel_dir_(chip_dir_ + "/pwm" + std::to_string(channel)),
      channel_(channel) {}

ptu::DriverStatus SysfsPwmChannel::open(long period_ns) {
    close();
    namespace fs = std::filesystem;
    std::error_code ignored;
    if (!fs::is_directory(channel_dir_, ignored)) {
        if (!write_file(chip_dir_ + "/export", channel_)) return failure("cannot export through", chip_dir_ + "/export");
        // udev applies the group and mode of the new files shortly after the export.
        for (int i = 0; i < 100 && !fs::exists(channel_dir_ + "/enable", ignored); ++i)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    const std::string period = channel_dir_ + "/period";
    if (!write_file(period, period_ns)) {
        // The kernel refuses a period below the current duty cycle: clear the duty cycle first.
        if (!write_file(channel_dir_ + "/duty_cycle", 0) || !write_file(period, period_ns))
            return failure("cannot write", period);
    }
    duty_fd_ = ::open((channel_dir_ + "/duty_cycle").c_str(), O_WRONLY | O_CLOEXEC);
    if (duty_fd_ < 0) return failure("cannot open", channel_dir_ + "/duty_cycle");
    enable_fd_ = ::open((channel_dir_ + "/enable").c_str(), O_WRONLY | O_CLOEXEC);
    if (enable_fd_ < 0) {
        ptu::DriverStatus status = failure("cannot open", channel_dir_ + "/enable");
        close();
        return status;
    }
    return ptu::DriverStatus::success();
}

void SysfsPwmChannel::close() {
    if (duty_fd_ >= 0) ::close(duty_fd_);
    if (enable_fd_ >= 0) ::close(enable_fd_);
    duty_fd_ = enable_fd_ = -1;
}

bool SysfsPwmChannel::set_duty_ns(long duty_ns, TimePoint& at) {
    const bool ok = duty_fd_ >= 0 && write_value(duty_fd_, duty_ns);
    at = MonoClock::now();
    return ok;
}

bool SysfsPwmChannel::set_enabled(bool enabled, TimePoint& at) {
    const bool ok = enable_fd_ >= 0 && write_value(enable_fd_, enabled ? 1 : 0);
    at = MonoClock::now();
    return ok;
}

}  // namespace rays::gpio
