// SPDX-License-Identifier: Apache-2.0
// How a test starts one of the built programs (raysd, raysctl, ptu-sim) as a child process: directly
// in a native build, through CMAKE_CROSSCOMPILING_EMULATOR (qemu-aarch64) in a cross build,
// since the machine running the tests has no binfmt handler for the target's executables.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/skip.hpp"

namespace rays::test {

// The emulator's words, empty in a native build (RAYS_EMULATOR and RAYS_BINARY_DIR, the build's top
// directory, are set by tests/CMakeLists.txt).
inline std::vector<std::string> emulator_words() {
    std::vector<std::string> words;
    std::istringstream in(RAYS_EMULATOR);
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

// argv with the emulator put in front of the first program of this build in it (an executable file
// under the build directory, not a config or socket path there): argv[0] itself, or the program a
// wrapper such as systemd-socket-activate starts; host programs (python3, socat) run as they are.
// The emulator's first word is looked up in PATH: start the result with execvp or posix_spawnp.
inline std::vector<std::string> emulated(std::vector<std::string> argv) {
    const std::string built = std::string(RAYS_BINARY_DIR) + "/";
    for (auto arg = argv.begin(); arg != argv.end(); ++arg) {
        if (!arg->starts_with(built) || !std::filesystem::is_regular_file(*arg) || ::access(arg->c_str(), X_OK) != 0)
            continue;
        std::vector<std::string> words = emulator_words();
        argv.insert(arg, words.begin(), words.end());
        break;
    }
    return argv;
}

// Under emulation, skips the calling test case (support/skip.hpp): for long simulations whose
// arithmetic the short cases of the same binary already run on the target, and which qemu-user
// would take minutes over. `why` names what stays covered.
inline void skip_under_emulation(const std::string& why) {
    if (!emulator_words().empty()) skip("under qemu-user: " + why);
}

// A shell command line that starts a program of this build, with the emulator in front, for std::system.
inline std::string emulated(const std::string& command) {
    std::string prefix = RAYS_EMULATOR;
    return prefix.empty() ? command : prefix + " " + command;
}

}  // namespace rays::test
