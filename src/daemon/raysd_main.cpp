// SPDX-License-Identifier: Apache-2.0
// raysd: the tracking daemon. See README.md and docs/protocol.md.
//   raysd [--config FILE]          run (default /etc/raysd/raysd.ini)
//   raysd --check-config FILE      validate the file and exit (0, or 78 with file:line)
//   raysd --stop-axes [--config F] stop the configured unit's axes and exit (systemd ExecStopPost)
//   raysd --sample-config          print config/raysd.ini's body: every key documented, for a real rig
#include <sysexits.h>

#include <cstdio>
#include <cstring>
#include <string>

#include "config/config_engine.hpp"
#include "core/clock.hpp"
#include "daemon/daemon.hpp"
#include "daemon/daemon_params.hpp"
#include "daemon/log.hpp"
#include "daemon/ptu_factory.hpp"

namespace {

using namespace rays::daemon;

constexpr const char* kDefaultConfig = "/etc/raysd/raysd.ini";

void usage(std::FILE* out) {
    std::fprintf(out,
                 "usage: raysd [--config FILE]\n"
                 "       raysd --check-config FILE\n"
                 "       raysd --stop-axes [--config FILE]\n"
                 "       raysd --sample-config\n"
                 "       raysd --version\n"
                 "Runs the Active Rays tracking daemon. FILE defaults to %s.\n",
                 kDefaultConfig);
}

int stop_axes(const DaemonConfig& config) {
    rays::SteadyClock clock;
    std::string error;
    auto driver = make_ptu_driver(config, clock, error);
    if (!driver) {
        log(Priority::Err, "stop axes: ptu.driver %s: %s", config.ptu.driver.c_str(), error.c_str());
        return 1;
    }
    if (rays::ptu::DriverStatus status = driver->configure(); !status.ok) {
        log(Priority::Err, "stop axes: PTU %s: %s", driver->name(), status.what());
        return 1;
    }
    driver->write(rays::ptu::PtuCommand::stop(), clock.now());
    driver->deactivate();
    log(Priority::Notice, "axes stopped (PTU %s)", driver->name());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::string config_path = kDefaultConfig;
    bool check_only = false;
    bool stop_only = false;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        bool has_value = i + 1 < argc;
        if ((arg == "--config" || arg == "-c") && has_value) {
            config_path = argv[++i];
        } else if (arg == "--check-config" && has_value) {
            config_path = argv[++i];
            check_only = true;
        } else if (arg == "--stop-axes") {
            stop_only = true;
        } else if (arg == "--sample-config") {
            std::fputs(rays::config::sample_ini(daemon_params(), rig_template()).c_str(), stdout);
            return 0;
        } else if (arg == "--version") {
            std::printf("raysd %s\n", RAYS_VERSION);
            return 0;
        } else if (arg == "--help" || arg == "-h") {
            usage(stdout);
            return 0;
        } else {
            std::fprintf(stderr, "raysd: unknown or incomplete option '%s'\n", arg.c_str());
            usage(stderr);
            return EX_USAGE;
        }
    }

    DaemonConfig config;
    if (auto problem = load_daemon_config(config_path, config)) {
        std::fprintf(stderr, "<3>%s\n", problem->to_string().c_str());
        return EX_CONFIG;
    }
    if (check_only) {  // the driver's settings must also work together; nothing is opened
        rays::SteadyClock clock;
        std::string error;
        if (!make_ptu_driver(config, clock, error)) {
            std::fprintf(stderr, "<3>%s: [%s] does not work for ptu.driver = %s: %s\n", config_path.c_str(),
                         config.ptu.driver.c_str(), config.ptu.driver.c_str(), error.c_str());
            return EX_CONFIG;
        }
        std::printf("%s: ok\n", config_path.c_str());
        return 0;
    }
    Priority level = Priority::Info;
    parse_priority(config.log.level, level);
    set_log_level(level);
    set_log_repeat_interval(std::chrono::duration<double>(config.log.repeat_interval_s));
    if (stop_only) return stop_axes(config);

    block_daemon_signals();
    rays::SteadyClock clock;
    Daemon daemon(config, config_path, {}, clock);
    return daemon.run();
}
