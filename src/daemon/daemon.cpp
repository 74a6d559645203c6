// SPDX-License-Identifier: Apache-2.0
#include "daemon/daemon.hpp"

#include <sys/signalfd.h>
#include <sysexits.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <future>
#include <thread>

#include "common/angles.hpp"
#include "common/frame_kernel.hpp"
#include "daemon/capture_thread.hpp"
#include "daemon/command_server.hpp"
#include "daemon/daemon_params.hpp"
#include "daemon/log.hpp"
#include "daemon/ptu_factory.hpp"
#include "daemon/realtime.hpp"
#include "daemon/replay_source.hpp"
#include "daemon/request_handler.hpp"
#include "daemon/service_notifier.hpp"
#include "daemon/sim_source.hpp"
#include "daemon/v4l2_source.hpp"
#include "drivers/calibrated_ptu.hpp"
#include "drivers/mock/mock_ptu.hpp"

namespace rays::daemon {
namespace {

sigset_t daemon_signals() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGHUP);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGINT);
    return set;
}

struct LoopStart {
    RealtimeReport priority;
    RealtimeReport affinity;
};

// mock.record_path: every command the simulated unit received, for tests and diagnosis.
void write_mock_records(const ptu::PtuDriver& driver, const std::string& path, TimePoint origin) {
    const auto* mock = dynamic_cast<const ptu::MockPtu*>(&driver);
    if (mock == nullptr || path.empty()) return;
    std::FILE* file = std::fopen(path.c_str(), "w");
    if (file == nullptr) {
        log(Priority::Err, "mock.record_path %s: %s", path.c_str(), std::strerror(errno));
        return;
    }
    std::fprintf(file, "time_s,accepted,pan_mode,pan,tilt_mode,tilt\n");
    for (const ptu::CommandRecord& record : mock->records()) {
        auto mode = [](const ptu::AxisCommand& axis) { return axis.mode == ptu::CommandMode::Velocity ? "velocity" : "position"; };
        std::fprintf(file, "%.6f,%d,%s,%.9g,%s,%.9g\n", std::chrono::duration<double>(record.time - origin).count(),
                     record.accepted ? 1 : 0, mode(record.command.axes[0]), record.command.axes[0].value,
                     mode(record.command.axes[1]), record.command.axes[1].value);
    }
    std::fclose(file);
}

}  // namespace

std::array<ptu::AxisCalibration, ptu::kAxes> calibration_of(const PtuSettings& ptu) {
    return {{{ptu.pan_inverted, ptu.pan_zero_deg * kRadPerDeg}, {ptu.tilt_inverted, ptu.tilt_zero_deg * kRadPerDeg}}};
}

void block_daemon_signals() {
    sigset_t set = daemon_signals();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    std::signal(SIGPIPE, SIG_IGN);
}

std::unique_ptr<FrameSource> open_frame_source(const DaemonConfig& config, const Clock& clock, std::string& error) {
    if (config.camera.source == "sim") return SimSource::open(config, clock, error);
    if (config.camera.source == "replay") return ReplaySource::open(config.camera, clock, error);
    return V4l2Source::open(config.camera, clock, error);
}


struct Daemon::Running {
    Running(const DaemonConfig& config, FrameSource& source, ptu::PtuDriver& driver, FrameObserver* observer,
            const Clock& clock)
        : channels(config.camera.queue_frames),
          calibrated(driver, calibration_of(config.ptu)),
          limiter(calibrated),
          loop(config, channels, limiter, notifier, clock, observer),
          capture(source, channels, clock) {}

    ServiceNotifier notifier;
    LoopChannels channels;
    ptu::CalibratedPtu calibrated;
    ptu::PtuLimiter limiter;
    FrameLoop loop;
    CaptureThread capture;
};

Daemon::Daemon(DaemonConfig config, std::string config_path, DaemonParts parts, const Clock& clock)
    : config_(std::move(config)), config_path_(std::move(config_path)), parts_(std::move(parts)), clock_(clock) {}

Daemon::~Daemon() = default;

void Daemon::request_stop() {
    if (!running_) return;
    running_->channels.stop.store(true);
    running_->channels.frames.wake();
}

int Daemon::run() {
    std::string error;
    if (!parts_.source) parts_.source = open_frame_source(config_, clock_, error);
    if (!parts_.source) {
        log(Priority::Err, "camera: %s", error.c_str());
        return 1;
    }
    if (!parts_.ptu) parts_.ptu = make_ptu_driver(config_, clock_, error);
    if (!parts_.ptu) {  // the driver's section does not work: a config error, as --check-config says
        log(Priority::Err, "ptu.driver %s: %s", config_.ptu.driver.c_str(), error.c_str());
        return EX_CONFIG;
    }
    RealtimeReport memory = lock_memory(config_.loop.lock_memory);
    if (memory.refused) log(Priority::Warning, "loop.lock_memory: %s", memory.text.c_str());

    running_ = std::make_unique<Running>(config_, *parts_.source, *parts_.ptu, parts_.observer, clock_);
    Running& r = *running_;
    if (auto* sim = dynamic_cast<SimSource*>(parts_.source.get())) sim->follow(r.channels);
    if (ptu::DriverStatus status = r.limiter.configure(); !status.ok) {
        log(Priority::Err, "PTU %s: %s", parts_.ptu->name(), status.what());
        return 1;
    }
    if (ptu::DriverStatus status = r.limiter.activate(); !status.ok) {
        log(Priority::Err, "PTU %s: %s", parts_.ptu->name(), status.what());
        r.limiter.deactivate();
        return 1;
    }
    std::optional<ListeningSocket> socket = ListeningSocket::open(config_.socket.path, error);
    if (!socket) {
        log(Priority::Err, "socket: %s", error.c_str());
        r.limiter.deactivate();
        return 1;
    }
    sigset_t signals = daemon_signals();
    int signal_fd = signalfd(-1, &signals, SFD_NONBLOCK | SFD_CLOEXEC);

    std::promise<LoopStart> started;
    std::thread loop_thread([&] {
        LoopStart start{set_fifo_priority(config_.loop.rt_priority), pin_to_cpu(config_.loop.cpu)};
        started.set_value(start);
        r.loop.run();
    });
    LoopStart start = started.get_future().get();
    for (const RealtimeReport* report : {&start.priority, &start.affinity})
        if (report->refused) log(Priority::Warning, "frame loop: %s", report->text.c_str());
    r.capture.start();

    DaemonFacts facts{parts_.ptu->name(), start.priority.text, start.affinity.text, memory.text, clock_.now()};
    RequestHandler handler(config_, r.channels, facts, [&] { return r.capture.status(); }, clock_);
    auto reload = [&] {
        DaemonConfig fresh;
        if (auto problem = load_daemon_config(config_path_, fresh)) {
            log(Priority::Err, "reload refused, running settings kept: %s", problem->to_string().c_str());
            return;
        }
        if (std::string fixed = changed_capacities(config_, fresh); !fixed.empty())
            log(Priority::Warning, "reload: %s changed, which takes a restart; kept the running values", fixed.c_str());
        copy_tunables(fresh, config_);
        if (!handler.push_tunables()) log(Priority::Err, "reload: the frame loop's command queue is full; try again");
        else log(Priority::Notice, "reloaded tunables from %s", config_path_.c_str());
    };
    std::string service_status;
    auto report_status = [&] {  // STATUS= for systemctl status, sent when it changes
        std::string now_status;
        r.channels.status.read([&](const LoopStatus& s) {
            now_status = std::string(to_string(s.last.state)) + ", " + to_string(s.mode) + " control, camera " +
                         (s.camera_connected ? "connected" : "AWAY") + ", PTU " + parts_.ptu->name() +
                         (s.ptu_fault ? std::string(" FAULT: ") + s.ptu_message.data() : std::string(" ok"));
        });
        if (now_status == service_status) return;
        service_status = now_status;
        r.notifier.status(service_status.c_str());
    };
    CommandServer server(config_.socket, *socket, signal_fd, r.channels, handler, reload, report_status);

    std::string ready = "tracking: " + parts_.source->describe() + ", PTU " + parts_.ptu->name() + ", " +
                        socket->describe() + ", frame kernels " + frame_kernel_build();
    log(Priority::Notice, "%s", ready.c_str());
    r.notifier.ready(ready.c_str());

    server.run();  // until SIGTERM/SIGINT or request_stop()
    r.notifier.stopping();
    r.channels.stop.store(true);
    r.channels.frames.close();
    loop_thread.join();  // the loop stops (and parks) the unit on its way out
    r.capture.stop(std::chrono::milliseconds(1000));
    write_mock_records(*parts_.ptu, config_.mock.record_path, facts.started);
    r.channels.log.drain();
    close(signal_fd);
    log(Priority::Notice, "stopped");
    return 0;
}

}  // namespace rays::daemon
