// SPDX-License-Identifier: Apache-2.0
// A configuration file written for one test and removed after it.
#pragma once
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace rays::test {

class TempIniFile {
public:
    explicit TempIniFile(const std::string& text) : path_(unique_path()) {
        std::ofstream(path_, std::ios::binary) << text;
    }
    ~TempIniFile() {
        std::error_code ignored;
        std::filesystem::remove(path_, ignored);
    }
    TempIniFile(const TempIniFile&) = delete;
    TempIniFile& operator=(const TempIniFile&) = delete;

    std::string path() const { return path_.string(); }

private:
    static std::filesystem::path unique_path() {
        static std::atomic<int> counter{0};
        return std::filesystem::temp_directory_path() /
               ("rays_config_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) + ".ini");
    }

    std::filesystem::path path_;
};

}  // namespace rays::test
