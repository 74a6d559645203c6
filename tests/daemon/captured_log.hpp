// SPDX-License-Identifier: Apache-2.0
// Sends this process's stderr (where raysd logs) to a file while alive, so a test can read the log.
#pragma once
#include <filesystem>
#include <string>

namespace rays::test {

class CapturedLog {
public:
    CapturedLog();
    ~CapturedLog();
    CapturedLog(const CapturedLog&) = delete;
    CapturedLog& operator=(const CapturedLog&) = delete;
    std::string text() const;  // what was written so far

private:
    std::filesystem::path path_;
    int saved_ = -1;
};

}  // namespace rays::test
