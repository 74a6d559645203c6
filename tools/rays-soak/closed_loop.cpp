// SPDX-License-Identifier: Apache-2.0
#include "closed_loop.hpp"

#include <cmath>
#include <cstdio>
#include <memory>

#include "common/angles.hpp"
#include "control/camera_model.hpp"
#include "daemon/daemon.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/loop_channels.hpp"
#include "daemon/ptu_factory.hpp"
#include "daemon/service_notifier.hpp"
#include "drivers/calibrated_ptu.hpp"
#include "daemon/sim_source.hpp"
#include "drivers/ptu_limiter.hpp"
#include "io/overlay.hpp"
#include "io/png_writer.hpp"
#include "sim/exposure_delay.hpp"
#include "soak_clock.hpp"

namespace rays::soak {
namespace {

using Seconds = std::chrono::duration<double>;

class LastFrame final : public daemon::FrameObserver {
public:
    void on_frame(const daemon::FrameTelemetry& frame) override { last = frame; }
    daemon::FrameTelemetry last;
};

// The frame as the loop saw it: its contour (green) and centre (blue), the true centre (red).
void write_overlay(const std::string& dir, long index, const daemon::LoopChannels& channels, Point truth) {
    channels.snapshot.read([&](const daemon::SnapshotFrame& snap) {
        io::RgbCanvas canvas(snap.image, 4);
        if (snap.has_contour) {
            std::vector<Point> contour(snap.contour.begin(), snap.contour.begin() + snap.points);
            canvas.polygon(contour, {40, 220, 40});
            canvas.cross(snap.ref, 8, {60, 60, 255});
        }
        canvas.cross(truth, 8, {255, 40, 40});
        char path[512];
        std::snprintf(path, sizeof path, "%s/frame-%06ld.png", dir.c_str(), index);
        std::string error;
        if (!io::write_png(path, canvas.width(), canvas.height(), 3, canvas.rgb().data(), error))
            std::fprintf(stderr, "rays-soak: %s: %s\n", path, error.c_str());
    });
}

}  // namespace

std::vector<SoakFrame> run_closed_loop(const SoakRun& run, std::string& error) {
    const daemon::DaemonConfig& config = run.config;
    std::unique_ptr<sim::SimCamera> sim_camera = daemon::make_sim_camera(config, error);
    if (!sim_camera) return {};

    SoakClock clock(run.lockstep);
    std::unique_ptr<ptu::PtuDriver> driver = daemon::make_ptu_driver(config, clock, error);
    if (!driver) return {};
    daemon::ServiceNotifier notifier;
    daemon::LoopChannels channels(config.camera.queue_frames);
    ptu::CalibratedPtu calibrated(*driver, daemon::calibration_of(config.ptu));
    ptu::PtuLimiter limiter(calibrated);
    LastFrame observer;
    auto loop = std::make_unique<daemon::FrameLoop>(config, channels, limiter, notifier, clock, &observer);
    if (ptu::DriverStatus status = limiter.configure(); !status.ok) {
        error = std::string("PTU: ") + status.what();
        return {};
    }
    if (ptu::DriverStatus status = limiter.activate(); !status.ok) {
        error = std::string("PTU: ") + status.what();
        return {};
    }
    channels.camera_connected.store(true);

    // The simulated rig is mounted facing the scenario's start: its pan/tilt zero looks there.
    const double pan0 = sim_camera->scenario().initial_pan_rad, tilt0 = sim_camera->scenario().initial_tilt_rad;
    const TimePoint origin = clock.now();
    auto view = std::make_unique<sim::SimView>();
    auto captured = std::make_unique<daemon::CapturedFrame>();
    std::vector<SoakFrame> frames;
    frames.reserve(static_cast<std::size_t>(run.frames));
    sim::ExposureDelay delay(config.sim.latency_frames, config.sim.fps, config.sim.stamp_exposure);
    for (long k = 0; k < run.frames; ++k) {
        const double t = static_cast<double>(k) / config.sim.fps;
        clock.set(origin + std::chrono::duration_cast<TimePoint::duration>(Seconds(t)));
        ptu::PtuState state;
        calibrated.read(state, clock.now());
        // With camera latency the picture (and its truth) is the one exposed latency_frames ago.
        const sim::ExposureDelay::Exposure exposure = delay.deliver(k, control::UnitPose::of(state, t));
        const control::UnitPose& unit = exposure.unit;
        sim_camera->render(exposure.t_s, unit.pan + pan0, unit.tilt + tilt0, *view);
        captured->image = view->image;
        captured->index = k;
        // Arrived now, after rendering (the simulator's own time is no part of the loop's latency).
        captured->arrived = clock.now();
        captured->stamp = captured->arrived - delay.stamp_lead(k);
        channels.frames.push(*captured, true, std::chrono::milliseconds(0));
        if (k == 0 && run.start_at_truth)
            channels.commands.push(daemon::make_command(daemon::CommandKind::Track, view->truth.mask_centroid_px.x,
                                                        view->truth.mask_centroid_px.y));
        loop->step();
        if (k % 256 == 0) channels.log.drain();

        const sim::SimTruth& truth = view->truth;
        SoakFrame f;
        f.t_s = t;
        f.truth_px = truth.visible_fraction > 0.5 ? truth.mask_centroid_px : truth.centre_px;
        f.target_in_image = truth.in_view && f.truth_px.x >= -0.5 && f.truth_px.x <= kFrameSize - 0.5 &&
                            f.truth_px.y >= -0.5 && f.truth_px.y <= kFrameSize - 0.5;
        f.has_contour = observer.last.frame == k && observer.last.has_contour;
        f.contour_px = {observer.last.ref_x, observer.last.ref_y};
        f.speed_deg_s = truth.speed_deg_s;
        f.speed_px_frame = truth.speed_px_per_s / config.sim.fps;
        f.latency_us = observer.last.latency_us;
        f.pan_deg = unit.pan * kDegPerRad;
        f.tilt_deg = unit.tilt * kDegPerRad;
        f.pan_rate_deg_s = unit.pan_rate * kDegPerRad;
        f.tilt_rate_deg_s = unit.tilt_rate * kDegPerRad;
        f.target_az_deg = control::angle_difference(truth.target.azimuth, pan0) * kDegPerRad;
        f.target_el_deg = (truth.target.elevation - tilt0) * kDegPerRad;
        frames.push_back(f);
        if (!run.overlay_dir.empty() && t >= run.overlay_from_s && t <= run.overlay_to_s)
            write_overlay(run.overlay_dir, k, channels, f.truth_px);
    }
    loop->stop_unit();
    channels.log.drain();
    return frames;
}

}  // namespace rays::soak
