// SPDX-License-Identifier: Apache-2.0
#include "captured_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

namespace rays::test {

CapturedLog::CapturedLog() : path_(std::filesystem::temp_directory_path() / ("raysd-test-log-" + std::to_string(getpid()) + ".txt")) {
    std::fflush(stderr);
    saved_ = dup(STDERR_FILENO);
    int fd = open(path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(fd, STDERR_FILENO);
    close(fd);
}

CapturedLog::~CapturedLog() {
    std::fflush(stderr);
    dup2(saved_, STDERR_FILENO);
    close(saved_);
    std::filesystem::remove(path_);
}

std::string CapturedLog::text() const {
    std::fflush(stderr);
    std::ifstream file(path_);
    std::stringstream content;
    content << file.rdbuf();
    return content.str();
}

}  // namespace rays::test
