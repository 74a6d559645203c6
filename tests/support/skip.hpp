// SPDX-License-Identifier: Apache-2.0
// Catch2 2 has no skip: a test that cannot run here says why and exits with 77, which CTest's
// SKIP_RETURN_CODE reports as skipped. Each TEST_CASE runs as its own CTest entry.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace rays::test {

[[noreturn]] inline void skip(const std::string& why) {
    std::printf("SKIPPED: %s\n", why.c_str());
    std::fflush(stdout);
    std::_Exit(77);
}

// ../shared beside the checkout: recorded sequences and the development scenes.
inline std::filesystem::path shared_dir_or_skip(const char* what) {
    std::filesystem::path dir = RAYS_SHARED_DIR;
    if (!std::filesystem::is_directory(dir))
        skip(std::string(what) + " needs " + dir.string() + ", which is absent on this machine");
    return dir;
}

}  // namespace rays::test
