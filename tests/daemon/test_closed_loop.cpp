// SPDX-License-Identifier: Apache-2.0
// The frame loop's closed-loop behaviour, run in-process against the simulated camera (src/sim) and
// the mock unit as rays-soak runs it (tools/rays-soak/closed_loop.cpp), but on purely simulated time
// (each step happens at its frame's capture instant: deterministic, no wall-clock waits), judged on
// the unit's recorded angles and the simulator's ground truth, never on the loop's own belief:
//  1. the soft angle limits, the velocity and the acceleration limit hold on every frame, for both
//     control laws, while the target runs far beyond the limits (and the unit does reach them);
//  2. ego-motion: while the unit moves (goto, jog), frame differencing never starts a track, also
//     not on the first frame after a stiff unit starts; once it stands still, a moving target is
//     detected and tracked;
//  3. the lost policy: after the target is released (or vanishes), the unit holds still for
//     lost_timeout_s, then goes home, or steps through search poses right and left of where it was;
//  4. coasting: frames without the target (rendered world only) keep the predictive law moving
//     the unit, and the track resumes on the target after them; without coasting the unit stops;
//  5. camera latency: frames stamped at exposure are paired with the unit's pose then (and the
//     target kept); the same frames stamped at delivery are not (and it is lost).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cctype>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "common/angles.hpp"
#include "control/camera_model.hpp"
#include "daemon/control_tunables.hpp"
#include "daemon/frame_loop.hpp"
#include "daemon/loop_channels.hpp"
#include "daemon/ptu_factory.hpp"
#include "daemon/service_notifier.hpp"
#include "daemon/sim_source.hpp"
#include "drivers/calibrated_ptu.hpp"
#include "drivers/ptu_limiter.hpp"
#include "sim/exposure_delay.hpp"
#include "sim/sim_camera.hpp"
#include "support/emulator.hpp"

namespace {

using namespace rays;
using namespace rays::daemon;
using Seconds = std::chrono::duration<double>;

constexpr double kOnTargetPx = 0.1 * kFrameSize;  // rays-soak's "on target": 10 % of the image size
constexpr std::uint64_t kWorldSeed = 5;

// Simulated time only: the loop sees every frame at its capture instant, so a run is reproducible
// and the tracker's deadline never cuts its refinement short, however loaded the machine.
class FrameClock final : public Clock {
public:
    TimePoint now() const override { return now_; }
    void set(TimePoint t) { now_ = t; }

private:
    TimePoint now_{std::chrono::seconds(1000)};
};

class LastFrame final : public FrameObserver {
public:
    void on_frame(const FrameTelemetry& frame) override { last = frame; }
    FrameTelemetry last;
};

struct FrameRecord {
    long k = 0;
    double t_s = 0;
    double pan_deg = 0, tilt_deg = 0;  // the unit at capture (rig angles), as rendered
    double pan_rate_deg_s = 0, tilt_rate_deg_s = 0;
    FrameTelemetry telemetry;          // what the loop made of this frame
    sim::SimTruth truth;
    Point truth_px;                    // the true target centre in the image (mask centroid when visible)
};

double distance_px(const FrameRecord& f) {
    if (!f.telemetry.has_contour) return 1e9;
    return std::hypot(f.telemetry.ref_x - f.truth_px.x, f.telemetry.ref_y - f.truth_px.y);
}

bool on_target(const FrameRecord& f) { return f.truth.in_view && distance_px(f) <= kOnTargetPx; }

std::unique_ptr<sim::SimCamera> camera_for(const DaemonConfig& config, sim::Scenario scenario) {
    const ControlTunables control = control_tunables(config.control, config.ptu.motion);
    return std::make_unique<sim::SimCamera>(std::move(scenario), control::CameraModel::from_intrinsics(control.intrinsics),
                                            sim::Panorama::generate(kWorldSeed));
}

// rays-soak's rig, one frame per step(): SimCamera → CapturedFrame → FrameLoop::step() →
// PtuLimiter → CalibratedPtu → the mock unit from make_ptu_driver. A hook sees each rendered view
// before the loop does: it may push commands or change the image.
class Rig {
public:
    // One rendered frame before the loop sees it: its view at world angles (pan, tilt), rad.
    struct Shot {
        long k;
        double t_s;
        double world_pan_rad, world_tilt_rad;
        sim::SimView& view;
    };
    using Hook = std::function<void(Shot& shot)>;

    Rig(const DaemonConfig& config, std::unique_ptr<sim::SimCamera> camera)
        : config_(config), camera_(std::move(camera)), channels_(config.camera.queue_frames) {
        REQUIRE(camera_ != nullptr);
        clock_.set(origin_);
        std::string error;
        driver_ = make_ptu_driver(config_, clock_, error);
        INFO(error);
        REQUIRE(driver_ != nullptr);
        calibrated_ = std::make_unique<ptu::CalibratedPtu>(*driver_, std::array<ptu::AxisCalibration, ptu::kAxes>{});
        limiter_ = std::make_unique<ptu::PtuLimiter>(*calibrated_);
        loop_ = std::make_unique<FrameLoop>(config_, channels_, *limiter_, notifier_, clock_, &observer_);
        REQUIRE(limiter_->configure().ok);
        REQUIRE(limiter_->activate().ok);
        channels_.camera_connected.store(true);
        frames_.reserve(4096);
    }

    ~Rig() {
        loop_->stop_unit();
        channels_.log.drain();
        if (const char* dir = std::getenv("RAYS_LOOP_TRACE")) {
            std::string name = Catch::getResultCapture().getCurrentTestName() + "-" + camera_->scenario().name;
            for (char& c : name)
                if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
            write_trace(std::string(dir) + "/" + name + ".csv");
        }
    }

    // For a closer look at a failure: RAYS_LOOP_TRACE=dir writes each run's frames there as CSV.
    void write_trace(const std::string& path) const {
        std::FILE* out = std::fopen(path.c_str(), "w");
        if (out == nullptr) return;
        std::fprintf(out, "k,t,pan,tilt,pan_rate,tilt_rate,mode,state,has_contour,ref_x,ref_y,truth_x,truth_y,in_view,"
                          "pan_cmd,tilt_cmd\n");
        for (const FrameRecord& f : frames_) {
            const FrameTelemetry& m = f.telemetry;
            std::fprintf(out, "%ld,%.2f,%.4f,%.4f,%.3f,%.3f,%d,%s,%d,%.1f,%.1f,%.1f,%.1f,%d,%.3f,%.3f\n", f.k, f.t_s,
                         f.pan_deg, f.tilt_deg, f.pan_rate_deg_s, f.tilt_rate_deg_s, static_cast<int>(m.mode),
                         to_string(m.state), m.has_contour, m.ref_x, m.ref_y, f.truth_px.x, f.truth_px.y,
                         f.truth.in_view, m.pan_cmd_deg_s, m.tilt_cmd_deg_s);
        }
        std::fclose(out);
    }

    void command(const LoopCommand& command) { REQUIRE(channels_.commands.push(command)); }

    const FrameRecord& step(const Hook& hook = nullptr) {
        const long k = static_cast<long>(frames_.size());
        const double t = static_cast<double>(k) / config_.sim.fps;
        clock_.set(origin_ + std::chrono::duration_cast<TimePoint::duration>(Seconds(t)));
        ptu::PtuState state;
        REQUIRE(calibrated_->read(state, clock_.now()).ok);
        // With camera latency (sim.latency_frames) the frame shows the world and the unit as they were
        // at its exposure, that many frames back; stamped then, or at delivery (sim.stamp_exposure).
        const sim::ExposureDelay::Exposure exposure = delay_.deliver(k, control::UnitPose::of(state, t));
        const control::UnitPose& unit = exposure.unit;
        const sim::Scenario& scenario = camera_->scenario();
        Shot shot{k, exposure.t_s, unit.pan + scenario.initial_pan_rad, unit.tilt + scenario.initial_tilt_rad, *view_};
        camera_->render(exposure.t_s, shot.world_pan_rad, shot.world_tilt_rad, *view_);
        if (hook) hook(shot);
        captured_->image = view_->image;
        captured_->index = k;
        captured_->arrived = clock_.now();
        captured_->stamp = captured_->arrived - delay_.stamp_lead(k);
        channels_.frames.push(*captured_, false, std::chrono::milliseconds(0));
        loop_->step();
        if (k % 256 == 0) channels_.log.drain();
        REQUIRE(observer_.last.frame == k);  // the loop processed this very frame

        FrameRecord& f = frames_.emplace_back();
        f.k = k;
        f.t_s = t;
        f.pan_deg = unit.pan * kDegPerRad;
        f.tilt_deg = unit.tilt * kDegPerRad;
        f.pan_rate_deg_s = unit.pan_rate * kDegPerRad;
        f.tilt_rate_deg_s = unit.tilt_rate * kDegPerRad;
        f.telemetry = observer_.last;
        f.truth = view_->truth;
        f.truth_px = view_->truth.visible_fraction > 0.5 ? view_->truth.mask_centroid_px : view_->truth.centre_px;
        return f;
    }

    void run_until(double t_s, const Hook& hook = nullptr) {
        while (static_cast<double>(frames_.size()) / config_.sim.fps < t_s) step(hook);
    }

    const std::vector<FrameRecord>& frames() const { return frames_; }
    double dt() const { return 1.0 / config_.sim.fps; }
    long frame_at(double t_s) const { return std::lround(t_s * config_.sim.fps); }

private:
    const DaemonConfig config_;
    const TimePoint origin_{std::chrono::seconds(1000)};
    FrameClock clock_;
    std::unique_ptr<sim::SimCamera> camera_;
    std::unique_ptr<sim::SimView> view_ = std::make_unique<sim::SimView>();
    std::unique_ptr<CapturedFrame> captured_ = std::make_unique<CapturedFrame>();
    sim::ExposureDelay delay_{config_.sim.latency_frames, config_.sim.fps, config_.sim.stamp_exposure};
    LoopChannels channels_;
    ServiceNotifier notifier_;
    LastFrame observer_;
    std::unique_ptr<ptu::PtuDriver> driver_;
    std::unique_ptr<ptu::CalibratedPtu> calibrated_;
    std::unique_ptr<ptu::PtuLimiter> limiter_;
    std::unique_ptr<FrameLoop> loop_;
    std::vector<FrameRecord> frames_;
};

// As `raysctl track` at the true target on the first frame (rays-soak's start_at_truth).
Rig::Hook track_truth_at_start(Rig& rig) {
    return [&rig](Rig::Shot& shot) {
        if (shot.k == 0)
            rig.command(make_command(CommandKind::Track, shot.view.truth.mask_centroid_px.x,
                                     shot.view.truth.mask_centroid_px.y));
    };
}

std::shared_ptr<const sim::Path> waves(double az_deg, double el_deg, std::vector<sim::Wave> az, std::vector<sim::Wave> el) {
    return std::make_shared<sim::WavePath>(control::WorldAngles{az_deg * kRadPerDeg, el_deg * kRadPerDeg}, std::move(az),
                                           std::move(el));
}

sim::Wave wave_deg(double amplitude_deg, double period_s, double phase = 0) {
    return sim::steady_wave(amplitude_deg * kRadPerDeg, period_s, phase);
}

// One textured dark disc on `path`, over the generated world, mild noise, fixed exposure; the rig
// faces the disc's start.
sim::Scenario disc_scenario(const char* name, std::shared_ptr<const sim::Path> path, sim::Presence presence = {}) {
    sim::Scenario s;
    s.name = name;
    s.seed = kWorldSeed;
    s.targets.push_back({sim::DiscShape{9}, 35, 12, 1.2, std::move(path), presence});
    s.noise_sigma = 2;
    const control::WorldAngles start = s.targets[0].path->at(0.0).position;
    s.initial_pan_rad = start.azimuth;
    s.initial_tilt_rad = start.elevation;
    return s;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Limits
// ---------------------------------------------------------------------------------------------

namespace {

double distance_to_limit(double angle, double lo, double hi) {
    return std::min(std::abs(angle - lo), std::abs(angle - hi));
}

void check_limits_hold(const std::string& law) {
    DaemonConfig config;
    config.sim.scenario = "soak";  // azimuth ±91°, elevation −8…+28°: far beyond the limits below
    config.control.law = law;
    PtuMotion& m = config.ptu.motion;
    m.pan_min_deg = -20;
    m.pan_max_deg = 25;
    m.tilt_min_deg = -5;
    m.tilt_max_deg = 10;
    m.max_velocity_deg_s = 40;
    m.max_accel_deg_s2 = 150;
    // The mock unit keeps its default dynamics (120 deg/s, 720 deg/s²): stiffer than the limits, so
    // only the limiter's shaping keeps the unit within them.
    std::string error;
    std::unique_ptr<sim::SimCamera> camera = make_sim_camera(config, error);
    INFO(error);
    REQUIRE(camera != nullptr);
    Rig rig(config, std::move(camera));
    const Rig::Hook start = track_truth_at_start(rig);
    for (int k = 0; k < 1500; ++k) rig.step(start);

    constexpr double kAngleTol = 0.05, kRateTol = 0.05, kAccelTol = 1.0;  // deg, deg/s, deg/s²
    // Within 2° of a soft limit the limiter may brake harder than max_accel for a frame: the stiffer
    // unit runs a little ahead of the limiter's prediction (ptu_limiter.hpp) and so finds itself past
    // its braking point. How far depends on the commands the tracked target leads to. Seen, with a
    // 150 deg/s² limit: up to 167 deg/s², and 187.5 deg/s² (predictive law, frame 714) once the
    // tracker's jump cost and contrast-scaled region term changed the contour it follows.
    constexpr double kNearLimitDeg = 2.0, kNearLimitAccelFactor = 1.3;
    const std::vector<FrameRecord>& frames = rig.frames();
    double pan_lo = 1e9, pan_hi = -1e9, tilt_lo = 1e9, tilt_hi = -1e9, rate_max = 0, accel_far = 0, accel_near = 0;
    double command_max = 0;
    long pan_lo_at = 0, pan_hi_at = 0, tilt_lo_at = 0, tilt_hi_at = 0, rate_at = 0, far_at = 0, near_at = 0, tracked = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
        const FrameRecord& f = frames[i];
        if (f.pan_deg < pan_lo) pan_lo = f.pan_deg, pan_lo_at = f.k;
        if (f.pan_deg > pan_hi) pan_hi = f.pan_deg, pan_hi_at = f.k;
        if (f.tilt_deg < tilt_lo) tilt_lo = f.tilt_deg, tilt_lo_at = f.k;
        if (f.tilt_deg > tilt_hi) tilt_hi = f.tilt_deg, tilt_hi_at = f.k;
        for (double rate : {f.pan_rate_deg_s, f.tilt_rate_deg_s})
            if (std::abs(rate) > rate_max) rate_max = std::abs(rate), rate_at = f.k;
        command_max = std::max({command_max, std::abs(static_cast<double>(f.telemetry.pan_cmd_deg_s)),
                                std::abs(static_cast<double>(f.telemetry.tilt_cmd_deg_s))});
        if (i > 0) {
            const FrameRecord& p = frames[i - 1];
            const bool pan_near = std::min(distance_to_limit(f.pan_deg, m.pan_min_deg, m.pan_max_deg),
                                           distance_to_limit(p.pan_deg, m.pan_min_deg, m.pan_max_deg)) < kNearLimitDeg;
            const bool tilt_near = std::min(distance_to_limit(f.tilt_deg, m.tilt_min_deg, m.tilt_max_deg),
                                            distance_to_limit(p.tilt_deg, m.tilt_min_deg, m.tilt_max_deg)) < kNearLimitDeg;
            const double accels[2] = {std::abs(f.pan_rate_deg_s - p.pan_rate_deg_s) / rig.dt(),
                                      std::abs(f.tilt_rate_deg_s - p.tilt_rate_deg_s) / rig.dt()};
            const bool near[2] = {pan_near, tilt_near};
            for (int axis = 0; axis < 2; ++axis) {
                double& worst = near[axis] ? accel_near : accel_far;
                long& worst_at = near[axis] ? near_at : far_at;
                if (accels[axis] > worst) worst = accels[axis], worst_at = f.k;
            }
        }
        if (on_target(f)) ++tracked;
    }
    INFO("law " << law << ": pan " << pan_lo << " (frame " << pan_lo_at << ") … " << pan_hi << " (frame " << pan_hi_at
                << "), tilt " << tilt_lo << " (frame " << tilt_lo_at << ") … " << tilt_hi << " (frame " << tilt_hi_at
                << "), |rate| ≤ " << rate_max << " (frame " << rate_at << "), |accel| ≤ " << accel_far << " (frame "
                << far_at << ") away from the limits, " << accel_near << " (frame " << near_at
                << ") near them; largest command " << command_max << " deg/s; on target " << tracked << " of "
                << frames.size() << " frames");
    CHECK(pan_lo >= m.pan_min_deg - kAngleTol);
    CHECK(pan_hi <= m.pan_max_deg + kAngleTol);
    CHECK(tilt_lo >= m.tilt_min_deg - kAngleTol);
    CHECK(tilt_hi <= m.tilt_max_deg + kAngleTol);
    CHECK(rate_max <= m.max_velocity_deg_s + kRateTol);
    CHECK(accel_far <= m.max_accel_deg_s2 + kAccelTol);
    CHECK(accel_near <= kNearLimitAccelFactor * m.max_accel_deg_s2);
    // Not vacuous: the loop followed the target, drove the unit to within 1° of a limit on both
    // axes, asked for the full velocity, turned at speed and changed speed at the full acceleration.
    CHECK(tracked > 300);
    CHECK((pan_hi >= m.pan_max_deg - 1.0 || pan_lo <= m.pan_min_deg + 1.0));
    CHECK((tilt_hi >= m.tilt_max_deg - 1.0 || tilt_lo <= m.tilt_min_deg + 1.0));
    CHECK(command_max >= m.max_velocity_deg_s - 0.01);
    CHECK(rate_max >= 15.0);
    CHECK(std::max(accel_far, accel_near) >= 0.9 * m.max_accel_deg_s2);
}

}  // namespace

TEST_CASE("closed loop: the unit stays within the soft limits, the velocity and the acceleration limit, predictive law") {
    rays::test::skip_under_emulation("minutes of simulated closed loop; the shorter closed-loop cases run the same loop on arm64");
    check_limits_hold("predictive");
}

TEST_CASE("closed loop: the unit stays within the soft limits, the velocity and the acceleration limit, proportional law") {
    rays::test::skip_under_emulation("minutes of simulated closed loop; the shorter closed-loop cases run the same loop on arm64");
    check_limits_hold("proportional");
}

// ---------------------------------------------------------------------------------------------
// 2. Ego-motion
// ---------------------------------------------------------------------------------------------

namespace {

// A unit that starts and stops gently (60 deg/s² in the limiter and in the mock's own profile for
// position moves): within the first frame after a command it moves less than 0.03° (0.06 px), so
// the ego-motion rule is tested on sustained motion. Stiff units: the next test case.
void gentle_unit(DaemonConfig& config) {
    config.ptu.motion.max_velocity_deg_s = 40;
    config.ptu.motion.max_accel_deg_s2 = 60;
    config.mock.max_velocity_deg_s = 40;
    config.mock.max_accel_deg_s2 = 60;
}

struct Detections {
    long moving = 0, still = 0;               // frames by the unit's motion since the previous capture
    long while_moving = 0, while_still = 0;   // of them: the tracker not in Detecting, or a contour
    long first = -1;                          // the first such frame
};

// Frames [from, to) with no moving target in the world: any track started there is false.
Detections detections(const Rig& rig, double still_deg_s, long from, long to) {
    Detections d;
    const std::vector<FrameRecord>& frames = rig.frames();
    for (long k = std::max(from, 1L); k < to && k < static_cast<long>(frames.size()); ++k) {
        const FrameRecord& f = frames[static_cast<std::size_t>(k)];
        const FrameRecord& p = frames[static_cast<std::size_t>(k - 1)];
        const bool moved = std::abs(f.pan_deg - p.pan_deg) > 0.005 || std::abs(f.tilt_deg - p.tilt_deg) > 0.005 ||
                           std::abs(f.pan_rate_deg_s) > still_deg_s || std::abs(f.tilt_rate_deg_s) > still_deg_s;
        const bool detected = f.telemetry.state != TrackState::Detecting || f.telemetry.has_contour;
        (moved ? d.moving : d.still) += 1;
        (moved ? d.while_moving : d.while_still) += detected;
        if (detected && d.first < 0) d.first = k;
    }
    return d;
}

// A disc standing at the rig's zero until `moves_at_s` (only the unit's own motion changes the
// view until then), then walking 20° right in 2 s and back.
sim::Scenario disc_standing_until(double moves_at_s) {
    const auto path = std::make_shared<sim::KeyframePath>(std::vector<sim::Keyframe>{
        {0, {0, 0}, 0, 0},
        {moves_at_s, {0, 0}, 0, 0},
        {moves_at_s + 2, {20 * kRadPerDeg, 0}, 0, 0},
        {moves_at_s + 4, {0, 0}, 0, 0},
        {moves_at_s + 6, {0, 0}, 0, 0}});
    return disc_scenario("ego-motion", path);
}

}  // namespace

TEST_CASE("closed loop: frame differencing never starts a track while the unit moves, and does once it stands still") {
    DaemonConfig config;
    gentle_unit(config);
    constexpr double kTargetMoves_s = 8.0;
    Rig rig(config, camera_for(config, disc_standing_until(kTargetMoves_s)));
    // Goto right and up, goto left and down, a jog (renewed every frame), goto back to zero.
    const Rig::Hook drive = [&rig](Rig::Shot& shot) {
        const long k = shot.k;
        if (k == 25) rig.command(make_command(CommandKind::Goto, 20 * kRadPerDeg, 6 * kRadPerDeg));
        if (k == 60) rig.command(make_command(CommandKind::Goto, -15 * kRadPerDeg, -4 * kRadPerDeg));
        if (k >= 105 && k < 130) rig.command(make_command(CommandKind::Jog, 12 * kRadPerDeg, -3 * kRadPerDeg));
        if (k == 135) rig.command(make_command(CommandKind::Goto, 0.0, 0.0));
    };
    rig.run_until(kTargetMoves_s + 4.0, drive);

    const Detections d = detections(rig, config.control.still_deg_s, 0, rig.frame_at(kTargetMoves_s));
    INFO(d.moving << " frames with the unit moving and " << d.still << " still before the target moves; "
                  << d.while_moving << " and " << d.while_still << " of them off Detecting; first: frame " << d.first);
    CHECK(d.moving >= 80);  // the unit really moved over the textured world, for a good while
    CHECK(d.while_moving == 0);
    CHECK(d.while_still == 0);  // nothing moves in the world: any track is false
    // The unit is back at rest, at zero, well before the target starts to move.
    const FrameRecord& settled = rig.frames()[static_cast<std::size_t>(rig.frame_at(kTargetMoves_s - 0.5))];
    CHECK(std::abs(settled.pan_deg) < 0.01);
    CHECK(std::abs(settled.tilt_deg) < 0.01);
    CHECK(std::abs(settled.pan_rate_deg_s) + std::abs(settled.tilt_rate_deg_s) == 0.0);

    // Once the target moves in front of the resting unit, detection finds it and the track stays on it.
    long acquired = -1, on = 0, after = 0;
    for (const FrameRecord& f : rig.frames()) {
        if (f.t_s < kTargetMoves_s) continue;
        if (acquired < 0 && f.telemetry.state == TrackState::Tracking) acquired = f.k;
        if (acquired >= 0 && f.k >= acquired + 3) {
            ++after;
            on += on_target(f);
        }
    }
    INFO("acquired at frame " << acquired << " (t = " << static_cast<double>(acquired) * rig.dt() << " s); on target "
                              << on << " of " << after << " frames after it");
    REQUIRE(acquired >= 0);
    CHECK(static_cast<double>(acquired) * rig.dt() < kTargetMoves_s + 1.0);
    CHECK(after >= 50);
    CHECK(static_cast<double>(on) >= 0.95 * static_cast<double>(after));
}

TEST_CASE("closed loop: frame differencing does not fire on the first frame after a stiff unit starts to move") {
    // The mock's default dynamics (720 deg/s², 10 ms latency): within the frame after a goto or a
    // jog is written the unit already turns by about 0.3° (0.7 px) across the textured world.
    DaemonConfig config;
    Rig rig(config, camera_for(config, disc_standing_until(100.0)));
    // Releases at rest between the moves drop a false track, if one began: each start is judged alone.
    const Rig::Hook drive = [&rig](Rig::Shot& shot) {
        const long k = shot.k;
        if (k == 25) rig.command(make_command(CommandKind::Goto, 20 * kRadPerDeg, 6 * kRadPerDeg));
        if (k == 45 || k == 80) rig.command(make_command(CommandKind::Release));
        if (k == 55) rig.command(make_command(CommandKind::Goto, 0.0, 0.0));
        if (k >= 90 && k < 105) rig.command(make_command(CommandKind::Jog, 15 * kRadPerDeg, 0.0));
    };
    rig.run_until(5.0, drive);
    const long kPhases[3][2] = {{25, 45}, {55, 80}, {90, 125}};
    const char* kNames[3] = {"goto from rest", "goto back", "jog from rest"};
    for (int i = 0; i < 3; ++i) {
        const Detections d = detections(rig, config.control.still_deg_s, kPhases[i][0], kPhases[i][1]);
        const FrameRecord& first = rig.frames()[static_cast<std::size_t>(std::max(d.first, kPhases[i][0]))];
        INFO(kNames[i] << ": frames " << kPhases[i][0] << "…" << kPhases[i][1] - 1 << ", " << d.moving
                       << " with the unit moving; first frame off Detecting: " << d.first << " (unit at pan "
                       << first.pan_deg << ", rate " << first.pan_rate_deg_s << " deg/s at its capture)");
        CHECK(d.moving >= 5);
        CHECK(d.while_moving + d.while_still == 0);
    }
}

// ---------------------------------------------------------------------------------------------
// 3. Lost policy
// ---------------------------------------------------------------------------------------------

namespace {

constexpr double kGone_s = 3.0;      // the target vanishes (and, where released, is released) here
constexpr double kTimeout_s = 1.2;   // control.lost_timeout_s
constexpr double kHomePan = -10.0, kHomeTilt = -6.0;

// A disc swinging 15° in azimuth (period 8 s) and 3° in elevation that vanishes at kGone_s, moving
// left at 8 deg/s from azimuth +10.6° then: the unit is moving, and 20° from home.
sim::Scenario vanishing_disc() {
    return disc_scenario("vanishing", waves(0, 0, {wave_deg(15, 8)}, {wave_deg(3, 11)}), sim::Presence{1000, 0, kGone_s});
}

DaemonConfig lost_config(const char* action) {
    DaemonConfig config;
    gentle_unit(config);  // so that a search or home move cannot start a false track (see above)
    config.control.lost_action = action;
    config.control.lost_timeout_s = kTimeout_s;
    config.control.search_step_deg = 5;
    config.control.search_steps = 2;
    config.control.search_dwell_s = 1.5;
    config.ptu.motion.home_pan_deg = kHomePan;
    config.ptu.motion.home_tilt_deg = kHomeTilt;
    return config;
}

const FrameRecord& at(const Rig& rig, double t_s) { return rig.frames()[static_cast<std::size_t>(rig.frame_at(t_s))]; }

// The unit was tracking the target, and turning, just before `t_s`.
void check_was_tracking(const Rig& rig, double t_s) {
    const FrameRecord& before = at(rig, t_s - 0.1);
    INFO("before the loss: pan " << before.pan_deg << " rate " << before.pan_rate_deg_s << ", contour "
                                 << distance_px(before) << " px from the truth");
    CHECK(on_target(before));
    CHECK(std::abs(before.pan_rate_deg_s) > 3.0);
}

// The frame where the loop gave up the target: the first from `from_s` on that commands a stop.
const FrameRecord& stop_frame(const Rig& rig, double from_s) {
    for (const FrameRecord& f : rig.frames())
        if (f.t_s >= from_s - 1e-9 && f.telemetry.pan_cmd_deg_s == 0.0f && f.telemetry.tilt_cmd_deg_s == 0.0f) return f;
    FAIL("the loop never stopped the unit after " << from_s << " s");
    return rig.frames().back();
}

// From the frame `lost` on: the unit comes to rest within 0.3 s and stays there until the lost
// timeout has run out. Returns the pose it held.
std::pair<double, double> check_holds(const Rig& rig, const FrameRecord& lost) {
    const FrameRecord& held = at(rig, lost.t_s + 0.3);
    double drift = 0, rate = 0;
    for (const FrameRecord& f : rig.frames()) {
        if (f.t_s < held.t_s || f.t_s >= lost.t_s + kTimeout_s - 1e-9) continue;
        drift = std::max({drift, std::abs(f.pan_deg - held.pan_deg), std::abs(f.tilt_deg - held.tilt_deg)});
        rate = std::max({rate, std::abs(f.pan_rate_deg_s), std::abs(f.tilt_rate_deg_s)});
    }
    INFO("lost at " << lost.t_s << " s at pan " << lost.pan_deg << "; held at pan " << held.pan_deg << ", tilt "
                    << held.tilt_deg << " from " << held.t_s << " s to " << lost.t_s + kTimeout_s << " s: drift "
                    << drift << " deg, rate up to " << rate << " deg/s");
    CHECK(std::abs(held.pan_deg - lost.pan_deg) < 1.0);
    CHECK(drift < 0.01);
    CHECK(rate == 0.0);
    return {held.pan_deg, held.tilt_deg};
}

void check_goes_home(const Rig& rig, const FrameRecord& lost, std::pair<double, double> held) {
    // Still at the held pose on the last frame of the timeout; home (20° away) within 1.6 s after it.
    const FrameRecord& last_held = at(rig, lost.t_s + kTimeout_s - 0.04);
    const FrameRecord& home = at(rig, lost.t_s + kTimeout_s + 1.6);
    INFO("lost at " << lost.t_s << " s; last frame of the timeout: pan " << last_held.pan_deg << "; at " << home.t_s
                    << " s: pan " << home.pan_deg << ", tilt " << home.tilt_deg);
    CHECK(std::abs(last_held.pan_deg - held.first) < 0.01);
    CHECK(std::abs(home.pan_deg - kHomePan) < 0.05);
    CHECK(std::abs(home.tilt_deg - kHomeTilt) < 0.05);
    CHECK(home.pan_rate_deg_s == 0.0);
}

// After coasting from `lost` on: the unit goes back to where the target was last seen (the world
// direction of the last contour's centre before `gone_s`), away from where coasting took it, and is
// at rest there by the end of the lost timeout. Returns that pose.
std::pair<double, double> check_goes_back(const Rig& rig, const DaemonConfig& config, const FrameRecord& lost,
                                          double gone_s) {
    const FrameRecord* seen = nullptr;
    for (const FrameRecord& f : rig.frames())
        if (f.t_s < gone_s && f.telemetry.has_contour) seen = &f;
    REQUIRE(seen != nullptr);
    const control::CameraModel camera =
        control::CameraModel::from_intrinsics(control_tunables(config.control, config.ptu.motion).intrinsics);
    const control::WorldAngles where = camera.world_angles({seen->telemetry.ref_x, seen->telemetry.ref_y},
                                                           seen->pan_deg * kRadPerDeg, seen->tilt_deg * kRadPerDeg);
    const double pan = where.azimuth / kRadPerDeg, tilt = where.elevation / kRadPerDeg;
    const FrameRecord& last_held = at(rig, lost.t_s + kTimeout_s - 0.04);
    INFO("last seen at " << seen->t_s << " s at pan " << pan << ", tilt " << tilt << "; coasted to pan " << lost.pan_deg
                         << " by " << lost.t_s << " s; at " << last_held.t_s << " s: pan " << last_held.pan_deg
                         << ", tilt " << last_held.tilt_deg << ", rate " << last_held.pan_rate_deg_s);
    CHECK(std::abs(lost.pan_deg - pan) > 3.0);  // coasting had taken the unit away from it
    CHECK(std::abs(last_held.pan_deg - pan) < 0.3);
    CHECK(std::abs(last_held.tilt_deg - tilt) < 0.3);
    CHECK(last_held.pan_rate_deg_s == 0.0);
    return {last_held.pan_deg, last_held.tilt_deg};
}

// Search poses 0, +1, −1, +2, −2 steps from `centre` (pan, tilt), where the target was lost at
// `lost_s`, each reached and held by the end of its dwell; tilt as it was.
void check_searches(const Rig& rig, const DaemonConfig& config, double lost_s, std::pair<double, double> centre) {
    const double dwell = config.control.search_dwell_s, step = config.control.search_step_deg;
    const std::array<double, 5> offsets{0, step, -step, 2 * step, -2 * step};
    for (std::size_t j = 0; j < offsets.size(); ++j) {
        const FrameRecord& f = at(rig, lost_s + kTimeout_s + static_cast<double>(j + 1) * dwell - 0.1);
        INFO("search pose " << j << " at " << f.t_s << " s: pan " << f.pan_deg << " (expected " << centre.first + offsets[j]
                            << "), tilt " << f.tilt_deg << " (expected " << centre.second << ")");
        CHECK(std::abs(f.pan_deg - (centre.first + offsets[j])) < 0.3);
        CHECK(std::abs(f.tilt_deg - centre.second) < 0.3);
        CHECK(f.pan_rate_deg_s == 0.0);
    }
}

Rig::Hook release_at(Rig& rig, double t_s) {
    const long k_release = rig.frame_at(t_s);
    return [&rig, k_release, start = track_truth_at_start(rig)](Rig::Shot& shot) {
        start(shot);
        if (shot.k == k_release) rig.command(make_command(CommandKind::Release));
    };
}

}  // namespace

TEST_CASE("closed loop: after release, the lost policy holds for the timeout, then goes home") {
    const DaemonConfig config = lost_config("home");
    Rig rig(config, camera_for(config, vanishing_disc()));
    rig.run_until(kGone_s + kTimeout_s + 2.0, release_at(rig, kGone_s));
    check_was_tracking(rig, kGone_s);
    const FrameRecord& released = at(rig, kGone_s);
    check_goes_home(rig, released, check_holds(rig, released));
}

TEST_CASE("closed loop: going home on a unit faster than the soft limit keeps to the soft velocity limit") {
    // PtuLimiter advances a position move's target at the soft limit and the simulated unit's profile
    // is set within it, as raysd sets a real drive's. A stiff unit three times faster than the limit
    // went home at 120 deg/s before either.
    DaemonConfig config = lost_config("home");
    config.mock.max_velocity_deg_s = 3.0 * config.ptu.motion.max_velocity_deg_s;
    config.mock.max_accel_deg_s2 = 720;
    Rig rig(config, camera_for(config, vanishing_disc()));
    rig.run_until(kGone_s + kTimeout_s + 2.0, release_at(rig, kGone_s));
    const FrameRecord& released = at(rig, kGone_s);
    double fastest = 0.0, furthest = 0.0;
    for (const FrameRecord& f : rig.frames()) {
        fastest = std::max({fastest, std::abs(f.pan_rate_deg_s), std::abs(f.tilt_rate_deg_s)});
        if (f.t_s > kGone_s) furthest = std::max(furthest, std::abs(f.pan_deg - released.pan_deg));
    }
    INFO("released at pan " << released.pan_deg << "; home pan " << kHomePan);
    CHECK(furthest > 10.0);  // it went (most of the way) home
    CHECK(fastest <= config.ptu.motion.max_velocity_deg_s + 1e-6);
}

TEST_CASE("closed loop: after release, the search policy holds for the timeout, then steps right and left of where it was") {
    const DaemonConfig config = lost_config("search");
    Rig rig(config, camera_for(config, vanishing_disc()));
    rig.run_until(kGone_s + kTimeout_s + 5 * config.control.search_dwell_s + 0.2, release_at(rig, kGone_s));
    check_was_tracking(rig, kGone_s);
    const FrameRecord& released = at(rig, kGone_s);
    check_holds(rig, released);
    check_searches(rig, config, released.t_s, {released.pan_deg, released.tilt_deg});
}

TEST_CASE("closed loop: when the target vanishes, the loop coasts, goes back to where it was last seen, holds for the timeout, then goes home") {
    const DaemonConfig config = lost_config("home");
    Rig rig(config, camera_for(config, vanishing_disc()));
    rig.run_until(kGone_s + config.control.coast_s + kTimeout_s + 2.0, track_truth_at_start(rig));
    check_was_tracking(rig, kGone_s);
    // Coasting: the unit follows the prediction for coast_s; then the loop gives up the target.
    const FrameRecord& lost = stop_frame(rig, kGone_s);
    CHECK(lost.t_s >= kGone_s + config.control.coast_s - 0.05);
    CHECK(lost.t_s <= kGone_s + config.control.coast_s + 0.05);
    check_goes_home(rig, lost, check_goes_back(rig, config, lost, kGone_s));
}

TEST_CASE("closed loop: when the target vanishes, the loop coasts, goes back to where it was last seen, holds, then searches around there") {
    const DaemonConfig config = lost_config("search");
    Rig rig(config, camera_for(config, vanishing_disc()));
    rig.run_until(kGone_s + config.control.coast_s + kTimeout_s + 5 * config.control.search_dwell_s + 0.2,
                  track_truth_at_start(rig));
    check_was_tracking(rig, kGone_s);
    const FrameRecord& lost = stop_frame(rig, kGone_s);
    check_searches(rig, config, lost.t_s, check_goes_back(rig, config, lost, kGone_s));
}

// ---------------------------------------------------------------------------------------------
// 4. Coasting
// ---------------------------------------------------------------------------------------------

namespace {

struct GapRun {
    std::vector<FrameRecord> frames;
    long gap_from = 0, gap_to = 0;  // frames [gap_from, gap_to) show the world without the target
};

// A disc swinging 25° in azimuth (period 16 s) and 4° in elevation, tracked from the first frame;
// from 8 s, where it passes the middle at 9.8 deg/s, `gap` frames show the world without it.
GapRun run_with_gap(const DaemonConfig& config, int gap) {
    const auto path = waves(0, 0, {wave_deg(25, 16)}, {wave_deg(4, 13, 1)});
    Rig rig(config, camera_for(config, disc_scenario("coast", path)));
    // The same world at the same time and angles with the target absent: what the camera sees
    // while the target is hidden.
    const auto empty = camera_for(config, disc_scenario("coast-empty", path, sim::Presence{1000, 999, 1000}));
    auto hidden = std::make_unique<sim::SimView>();
    GapRun run;
    run.gap_from = rig.frame_at(8.0);
    run.gap_to = run.gap_from + gap;
    const Rig::Hook start = track_truth_at_start(rig);
    rig.run_until(11.0, [&](Rig::Shot& shot) {
        start(shot);
        if (shot.k < run.gap_from || shot.k >= run.gap_to) return;
        empty->render(shot.t_s, shot.world_pan_rad, shot.world_tilt_rad, *hidden);
        REQUIRE_FALSE(hidden->truth.in_view);
        shot.view.image = hidden->image;
    });
    run.frames = rig.frames();
    return run;
}

}  // namespace

TEST_CASE("closed loop: the predictive law coasts through frames without the target and the track resumes on it") {
    DaemonConfig config;
    config.control.law = "predictive";
    constexpr int kGap = 5;
    const GapRun run = run_with_gap(config, kGap);
    const std::vector<FrameRecord>& frames = run.frames;
    const auto gap_from = static_cast<std::size_t>(run.gap_from), gap_to = static_cast<std::size_t>(run.gap_to);

    // On target up to the gap.
    long on_before = 0;
    for (std::size_t i = gap_from - 50; i < gap_from; ++i) on_before += on_target(frames[i]);
    CHECK(on_before == 50);

    // Through the gap: no contour (the target really is gone from those frames), yet the controller
    // keeps commanding the target's speed and the unit keeps turning.
    for (std::size_t i = gap_from; i < gap_to; ++i) {
        const FrameRecord& f = frames[i];
        INFO("gap frame " << f.k << ": state " << to_string(f.telemetry.state) << ", commanded pan "
                          << f.telemetry.pan_cmd_deg_s << " deg/s, unit pan rate " << f.pan_rate_deg_s << " deg/s");
        CHECK_FALSE(f.telemetry.has_contour);
        CHECK(std::abs(f.telemetry.pan_cmd_deg_s) > 3.0);
        CHECK(std::abs(f.pan_rate_deg_s) > 3.0);
    }

    // After it: back on the target within 5 frames, and on it from then to the end.
    std::size_t back = gap_to;
    while (back < frames.size() && !on_target(frames[back])) ++back;
    long on_after = 0;
    for (std::size_t i = back; i < frames.size(); ++i) on_after += on_target(frames[i]);
    INFO("back on target at frame " << (back < frames.size() ? frames[back].k : -1) << " (gap ends at frame "
                                    << run.gap_to << "); on target " << on_after << " of " << frames.size() - back
                                    << " frames from then");
    REQUIRE(back < frames.size());
    CHECK(back - gap_to <= 5);
    CHECK(static_cast<double>(on_after) >= 0.98 * static_cast<double>(frames.size() - back));
}

TEST_CASE("closed loop: without coasting (coast_s = 0) the same gap stops the unit") {
    // The control for the test above: the assertion on the command through the gap can fail.
    DaemonConfig config;
    config.control.law = "predictive";
    config.control.coast_s = 0.0;
    const GapRun run = run_with_gap(config, 5);
    const FrameRecord& last = run.frames[static_cast<std::size_t>(run.gap_to - 1)];
    INFO("last gap frame " << last.k << ": commanded pan " << last.telemetry.pan_cmd_deg_s << " deg/s");
    CHECK(last.telemetry.pan_cmd_deg_s == 0.0f);
}

TEST_CASE("closed loop: a contour seen for a few frames after a gap does not set the unit coasting") {
    // The disc is tracked to 8 s; then 3 frames without it, then 4 frames with a decoy: a copy of it
    // held at one place in the image, 12 px right of and 10 px above where the disc was, whatever the
    // unit does (something that moves with the camera); then nothing. The decoy's sightings give the
    // controller the unit's own rate and more toward the decoy: coasting on that after it vanishes
    // would run the unit on. Seen only 4 frames in a row, it is not coasted on: the unit holds.
    DaemonConfig config;
    config.control.law = "predictive";
    const auto path = waves(0, 0, {wave_deg(25, 16)}, {wave_deg(4, 13, 1)});
    Rig rig(config, camera_for(config, disc_scenario("decoy", path)));
    const auto empty = camera_for(config, disc_scenario("decoy-empty", path, sim::Presence{1000, 999, 1000}));
    auto hidden = std::make_unique<sim::SimView>();
    auto last_seen = std::make_unique<sim::SimView>();
    const long gap_from = rig.frame_at(8.0), decoy_from = gap_from + 3, decoy_to = decoy_from + 4;
    const Rig::Hook start = track_truth_at_start(rig);
    rig.run_until(10.0, [&](Rig::Shot& shot) {
        start(shot);
        if (shot.k == gap_from - 1) *last_seen = shot.view;
        if (shot.k < gap_from) return;
        empty->render(shot.t_s, shot.world_pan_rad, shot.world_tilt_rad, *hidden);
        shot.view.image = hidden->image;
        if (shot.k < decoy_from || shot.k >= decoy_to) return;
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const int dx = x + 12, dy = y - 10;
                if (last_seen->mask.at(x, y) && dx < kFrameSize && dy >= 0) shot.view.image.at(dx, dy) = last_seen->image.at(x, y);
            }
    });
    const std::vector<FrameRecord>& frames = rig.frames();
    long decoy_seen = 0;
    for (long k = decoy_from; k < decoy_to; ++k) decoy_seen += frames[static_cast<std::size_t>(k)].telemetry.has_contour;
    INFO("the decoy was seen in " << decoy_seen << " of its 4 frames");
    REQUIRE(decoy_seen >= 2);  // else the test shows nothing
    // From two frames after the decoy on: no contour, no command, and the unit stays within a degree.
    const FrameRecord& held = frames[static_cast<std::size_t>(decoy_to + 2)];
    for (std::size_t i = static_cast<std::size_t>(decoy_to + 2); i < frames.size(); ++i) {
        const FrameRecord& f = frames[i];
        INFO("frame " << f.k << ": contour " << f.telemetry.has_contour << ", commanded " << f.telemetry.pan_cmd_deg_s
                      << " / " << f.telemetry.tilt_cmd_deg_s << " deg/s, unit at " << f.pan_deg << " / " << f.tilt_deg);
        CHECK_FALSE(f.telemetry.has_contour);
        CHECK(f.telemetry.pan_cmd_deg_s == 0.0f);
        CHECK(f.telemetry.tilt_cmd_deg_s == 0.0f);
        CHECK(std::abs(f.pan_deg - held.pan_deg) <= 1.0);
        CHECK(std::abs(f.tilt_deg - held.tilt_deg) <= 1.0);
    }
}

// ---------------------------------------------------------------------------------------------
// 5. Camera latency
// ---------------------------------------------------------------------------------------------

namespace {

// The speed ramp on rays-soak's fast rig (tools/rays-soak/fast-rig.ini): a 30° lens, frames
// delivered three frame periods after their exposure, a 400 deg/s unit, the predictive law with the
// constant-acceleration model. Runs 60 s (the swings' peak speed reaches 153 deg/s); returns the
// share of frames on target.
double ramp_with_latency(bool stamp_exposure) {
    DaemonConfig config;
    config.sim.scenario = "ramp";
    config.sim.latency_frames = 3;
    config.sim.stamp_exposure = stamp_exposure;
    config.ptu.driver = "mock";
    config.ptu.motion.max_velocity_deg_s = 400;
    config.ptu.motion.max_accel_deg_s2 = 3000;
    config.mock.max_velocity_deg_s = 450;
    config.mock.max_accel_deg_s2 = 4000;
    config.control.horizontal_fov_deg = config.control.vertical_fov_deg = 30;
    config.control.law = "predictive";
    config.control.target_motion = "acceleration";
    config.control.target_jerk_deg_s3 = 10000;
    config.control.gain = 10;
    std::string error;
    Rig rig(config, make_sim_camera(config, error));
    rig.run_until(60.0, track_truth_at_start(rig));
    long on = 0;
    for (const FrameRecord& f : rig.frames()) on += on_target(f);
    return static_cast<double>(on) / static_cast<double>(rig.frames().size());
}

}  // namespace

TEST_CASE("closed loop: with camera latency, each frame is paired with the unit's pose at its exposure") {
    rays::test::skip_under_emulation("minutes of simulated closed loop; the shorter closed-loop cases run the same loop on arm64");
    // Stamped at exposure (as V4L2 stamps buffers), the loop takes the unit's pose at that instant
    // from its pose history, and the target is kept. The control: the same frames stamped at
    // delivery, which pairs each with the pose 120 ms later, misplace the target in the world by the
    // unit's travel in that time and lose it.
    const double stamped = ramp_with_latency(true);
    const double unstamped = ramp_with_latency(false);
    INFO("on target: stamped at exposure " << stamped << ", stamped at delivery " << unstamped);
    CHECK(stamped >= 0.95);
    CHECK(unstamped <= 0.5);
}
