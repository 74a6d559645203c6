// SPDX-License-Identifier: Apache-2.0
#include "daemon/sim_source.hpp"

#include <cstdio>
#include <thread>

#include "control/controller.hpp"
#include "daemon/control_tunables.hpp"

namespace rays::daemon {
namespace {

using Seconds = std::chrono::duration<double>;

}  // namespace

std::unique_ptr<sim::SimCamera> make_sim_camera(const DaemonConfig& config, std::string& error) {
    const auto seed = static_cast<std::uint64_t>(config.sim.seed);
    std::optional<sim::Scenario> scenario = sim::make_scenario(config.sim.scenario, seed);
    if (!scenario) {
        error = "sim.scenario '" + config.sim.scenario + "' is not a known scenario";
        return nullptr;
    }
    std::optional<sim::Panorama> world = config.sim.panorama_png.empty()
                                             ? std::optional<sim::Panorama>(sim::Panorama::generate(seed))
                                             : sim::Panorama::load_png(config.sim.panorama_png, error);
    if (!world) {
        error = "sim.panorama_png: " + error;
        return nullptr;
    }
    const ControlTunables control = control_tunables(config.control, config.ptu.motion);
    return std::make_unique<sim::SimCamera>(std::move(*scenario), control::CameraModel::from_intrinsics(control.intrinsics),
                                            std::move(*world));
}

std::unique_ptr<SimSource> SimSource::open(const DaemonConfig& config, const Clock& clock, std::string& error) {
    std::unique_ptr<sim::SimCamera> camera = make_sim_camera(config, error);
    if (!camera) return nullptr;
    return std::unique_ptr<SimSource>(new SimSource(config.sim, std::move(camera), clock));
}

SimSource::SimSource(const SimSettings& settings, std::unique_ptr<sim::SimCamera> camera, const Clock& clock)
    : settings_(settings),
      camera_(std::move(camera)),
      view_(std::make_unique<sim::SimView>()),
      clock_(clock),
      delay_(settings.latency_frames, settings.fps, settings.stamp_exposure) {}

void SimSource::unit_angles(TimePoint at, double& pan, double& tilt) const {
    pan = tilt = 0.0;
    const LoopChannels* channels = channels_.load();
    if (channels == nullptr) return;
    channels->status.read([&](const LoopStatus& status) {
        const ptu::PtuState& unit = status.ptu;
        const double ahead = unit.stamp == TimePoint{} ? 0.0 : Seconds(at - unit.stamp).count();
        const control::UnitPose then = control::UnitPose::of(unit, 0.0).at(ahead);
        pan = then.pan;
        tilt = then.tilt;
    });
}

FrameSource::Result SimSource::next(CapturedFrame& out, std::chrono::milliseconds timeout) {
    if (delivered_ == 0) start_ = clock_.now();
    const TimePoint due =
        start_ + std::chrono::duration_cast<TimePoint::duration>(Seconds(static_cast<double>(delivered_) / settings_.fps));
    const TimePoint now = clock_.now();
    if (due - now > timeout) {
        std::this_thread::sleep_for(timeout);
        return Result::Timeout;
    }
    if (due > now) std::this_thread::sleep_until(MonoClock::now() + (due - now));
    double pan = 0.0, tilt = 0.0;
    unit_angles(due, pan, tilt);
    // With latency, the picture is the one exposed latency_frames ago, at the pose of that moment.
    const sim::ExposureDelay::Exposure then = delay_.deliver(delivered_, {Seconds(due - start_).count(), pan, tilt, 0, 0});
    const sim::Scenario& scenario = camera_->scenario();
    camera_->render(then.t_s, then.unit.pan + scenario.initial_pan_rad, then.unit.tilt + scenario.initial_tilt_rad, *view_);
    out.image = view_->image;
    out.chroma.present = false;  // the simulated camera is grey
    out.stamp = due - delay_.stamp_lead(delivered_);
    out.index = delivered_++;
    return Result::Frame;
}

std::string SimSource::describe() const {
    char text[160];
    std::snprintf(text, sizeof text, "simulated camera, scenario %s seed %d at %g fps, frame %ld",
                  settings_.scenario.c_str(), settings_.seed, settings_.fps, delivered_);
    return text;
}

}  // namespace rays::daemon
