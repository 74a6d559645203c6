// SPDX-License-Identifier: Apache-2.0
// libFuzzer target: the input as raysd's INI file into load_daemon_config. A file that loads must
// load the same from its sample_ini echo; an error names a line (0: the file as a whole).
#include <cstddef>
#include <cstdint>
#include <string>

#include "config/config_engine.hpp"
#include "daemon/daemon_params.hpp"
#include "fuzz_support.hpp"

using rays::fuzz::expect;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static rays::fuzz::MemoryFile file;
    const auto& table = rays::daemon::daemon_params();
    file.write(data, size);
    rays::daemon::DaemonConfig config;
    if (auto error = rays::daemon::load_daemon_config(file.path(), config)) {
        expect(!error->message.empty(), "an error has a message");
        expect(error->line >= 0, "an error's line is not negative");
        expect(error->file == file.path(), "an error names the file");
        expect(rays::config::to_json(table, config) == rays::config::to_json(table, rays::daemon::DaemonConfig{}),
               "a failed load leaves the config as it was");
        return 0;
    }
    const std::string echo = rays::config::sample_ini(table, config);
    file.write(echo.data(), echo.size());
    rays::daemon::DaemonConfig again;
    auto error = rays::daemon::load_daemon_config(file.path(), again);
    if (error) std::fprintf(stderr, "%s\n", error->to_string().c_str());
    expect(!error, "the sample_ini echo of a loaded config loads");
    expect(rays::config::to_json(table, config) == rays::config::to_json(table, again),
           "the sample_ini echo loads to the same config");
    return 0;
}
