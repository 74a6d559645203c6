// SPDX-License-Identifier: Apache-2.0
#include "daemon/frame_loop.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <thread>

#include "common/angles.hpp"
#include "snake/tracker_factory.hpp"

namespace rays::daemon {
namespace {

using Seconds = std::chrono::duration<double>;
using Micros = std::chrono::duration<float, std::micro>;

// The loop writes to the unit at least this often, frames or not, so the limiter's braking plan holds.
constexpr Seconds kLongestWait{0.05};
constexpr double kArrivalS = 0.1;         // a position command this many seconds of still-rate away has arrived
// The prediction is followed while the target is out of sight only if it was seen this many frames in
// a row before: a contour found for a frame or two after a gap (on something else, or on something
// that moves with the camera) gives the controller a rate it would run the unit away on.
constexpr int kCoastRun = 10;

ptu::PtuCommand position_command(double pan_rad, double tilt_rad) {
    ptu::PtuCommand command;
    command.axes[0] = {ptu::CommandMode::Position, pan_rad};
    command.axes[1] = {ptu::CommandMode::Position, tilt_rad};
    return command;
}

float velocity_deg_s(const ptu::AxisCommand& axis) {
    return axis.mode == ptu::CommandMode::Velocity ? static_cast<float>(axis.value * kDegPerRad) : 0.0f;
}

ptu::PtuLimits limits_of(const PtuMotion& motion) {
    ptu::PtuLimits limits;
    limits.axes[0] = {motion.pan_min_deg * kRadPerDeg, motion.pan_max_deg * kRadPerDeg,
                      motion.max_velocity_deg_s * kRadPerDeg, motion.max_accel_deg_s2 * kRadPerDeg};
    limits.axes[1] = {motion.tilt_min_deg * kRadPerDeg, motion.tilt_max_deg * kRadPerDeg,
                      motion.max_velocity_deg_s * kRadPerDeg, motion.max_accel_deg_s2 * kRadPerDeg};
    limits.command_interval_s = kLongestWait.count();
    return limits;
}

}  // namespace

FrameLoop::FrameLoop(const DaemonConfig& config, LoopChannels& channels, ptu::PtuLimiter& ptu,
                     ServiceNotifier& notifier, const Clock& clock, FrameObserver* observer)
    : channels_(channels),
      ptu_(ptu),
      notifier_(notifier),
      clock_(clock),
      observer_(observer),
      tracker_(make_tracker(config.tracker, clock)),
      tunables_(loop_tunables(config)),
      proportional_(control::CameraModel::from_intrinsics(tunables_.control.intrinsics), tunables_.control.controller),
      predictive_(control::CameraModel::from_intrinsics(tunables_.control.intrinsics), tunables_.control.controller,
                  tunables_.control.filter),
      controller_(nullptr),
      require_homing_(config.ptu.require_homing),
      frame_timeout_(std::chrono::duration_cast<std::chrono::nanoseconds>(Seconds(config.camera.frame_timeout_s))),
      wait_(std::chrono::duration_cast<std::chrono::nanoseconds>(std::min(kLongestWait, Seconds(config.camera.frame_timeout_s)))),
      started_(clock.now()) {
    ptu_.set_limits(limits_of(tunables_.ptu));
    set_controllers();
}

void FrameLoop::set_controllers() {
    control::CameraModel camera = control::CameraModel::from_intrinsics(tunables_.control.intrinsics);
    control::ControllerSettings settings = tunables_.control.controller;
    settings.lead_s += ptu_.command_latency_s();
    proportional_ = control::ProportionalController(camera, settings);
    predictive_ = control::PredictiveController(camera, settings, tunables_.control.filter);
    controller_ = tunables_.control.predictive ? static_cast<control::Controller*>(&predictive_) : &proportional_;
    lost_policy_.set_settings(tunables_.control.lost);
}

bool FrameLoop::commands_motion() const {
    for (std::size_t axis = 0; axis < ptu::kAxes; ++axis) {
        const ptu::AxisCommand& c = commanded_.axes[axis];
        const double off = c.mode == ptu::CommandMode::Velocity ? std::abs(c.value)
                                                                : std::abs(c.value - unit_.axes[axis].position_rad) / kArrivalS;
        if (off > tunables_.control.still_rad_s) return true;
    }
    return false;
}

double FrameLoop::seconds(TimePoint t) const { return Seconds(t - started_).count(); }

control::UnitPose FrameLoop::unit_pose(TimePoint t) const { return pose_history_.at(seconds(t)); }

void FrameLoop::run() {
    while (!channels_.stop.load(std::memory_order_acquire)) step();
    stop_unit();
}

void FrameLoop::step() {
    frame_fresh_ = channels_.frames.pop(frame_, wait_);
    TimePoint step_start = clock_.now();
    if (!frame_fresh_) ++stats_.frame_timeouts;

    LoopCommand command;
    while (channels_.commands.pop(command)) apply(command, step_start);

    bool connected = channels_.camera_connected.load(std::memory_order_acquire);
    if (connected != camera_was_connected_)
        channels_.log.log(connected ? Priority::Notice : Priority::Warning,
                          connected ? "camera back: tracking resumes" : "camera away: axes stopped");
    camera_was_connected_ = connected;

    if (frame_fresh_) track_frame(step_start);
    drive_unit(clock_.now());
    publish(clock_.now(), step_start);
    notifier_.feed_watchdog(clock_.now());
}

void FrameLoop::apply(const LoopCommand& command, TimePoint now) {
    switch (command.kind) {
    case CommandKind::Tunables: apply_tunables(command.tunables); return;
    case CommandKind::Track:
    case CommandKind::TrackBox:
        // The user's target replaces whatever is tracked or coasted, from the next frame on.
        tracker_->release();
        controller_->lost();
        sighted_run_ = run_before_gap_ = 0;  // the new target's sightings count from its first
        if (command.kind == CommandKind::Track) tracker_->start_at({command.a, command.b});
        else tracker_->start_in(command.box);  // the request handler checked it with box_problem()
        mode_ = ControlMode::Automatic;
        return;
    case CommandKind::Release:
    case CommandKind::Reinit: {
        if (command.kind == CommandKind::Release) tracker_->release();
        else tracker_->reinit();
        controller_->lost();
        const control::UnitPose pose = unit_pose(now);
        lost_policy_.lost_at(pose.t_s, pose.pan, pose.tilt);
        return;
    }
    case CommandKind::Resume: mode_ = ControlMode::Automatic; return;
    case CommandKind::Jog:
        manual_ = {};
        manual_.axes[0].value = command.a;
        manual_.axes[1].value = command.b;
        jog_expires_ = now + std::chrono::duration_cast<TimePoint::duration>(Seconds(tunables_.ptu.command_timeout_s));
        jogging_ = true;
        break;
    case CommandKind::Goto: manual_ = position_command(command.a, command.b); break;
    case CommandKind::Home:
        if (ptu::DriverStatus homing = ptu_.home(now); !homing.ok)
            channels_.log.log(Priority::Notice, "ptu home: %s; moving to the home angles", homing.what());
        manual_ = position_command(tunables_.ptu.home_pan_deg * kRadPerDeg, tunables_.ptu.home_tilt_deg * kRadPerDeg);
        break;
    case CommandKind::Park:
        manual_ = position_command(tunables_.ptu.park_pan_deg * kRadPerDeg, tunables_.ptu.park_tilt_deg * kRadPerDeg);
        break;
    case CommandKind::Stop: manual_ = ptu::PtuCommand::stop(); break;
    }
    if (command.kind != CommandKind::Jog) jogging_ = false;
    mode_ = ControlMode::Manual;
}

void FrameLoop::apply_tunables(const LoopTunables& tunables) {
    if (!tracker_->set_tunables(tunables.tracker)) {
        channels_.log.log(Priority::Err, "new tracker settings do not fit the capacities; kept the old ones");
        return;
    }
    tunables_ = tunables;
    ptu_.set_limits(limits_of(tunables_.ptu));
    set_controllers();
}

void FrameLoop::track_frame(TimePoint now) {
    // The budget counts from the frame's arrival: a camera's stamp (its exposure) may be well before.
    const TimePoint arrived = frame_.arrived == TimePoint{} ? frame_.stamp : frame_.arrived;
    TimePoint deadline =
        arrived + std::chrono::duration_cast<TimePoint::duration>(
                           std::chrono::duration<double, std::milli>(tunables_.budget_ms));
    if (deadline <= now) ++stats_.late_frames;
    last_frame_at_ = now;
    TimePoint begin = clock_.now();
    const control::UnitPose at_capture = unit_pose(frame_.stamp);
    // The reported rates lag a command by the unit's latency, so a command that moves it counts too.
    const bool still = std::abs(at_capture.pan_rate) <= tunables_.control.still_rad_s &&
                       std::abs(at_capture.tilt_rate) <= tunables_.control.still_rad_s && !commands_motion();
    tracker_->allow_detection(still && still_at_last_frame_);  // ego-motion: difference only still views
    still_at_last_frame_ = still;
    // How far the unit's own turning moved the view since the last frame (the tracker's motion layers).
    const auto camera = control::CameraModel::from_intrinsics(tunables_.control.intrinsics);
    tracker_->expect_view_shift(last_capture_ ? camera.view_shift(last_capture_->pan, last_capture_->tilt, at_capture.pan, at_capture.tilt)
                                              : std::nullopt);
    last_capture_ = at_capture;
    const bool coasting = !telemetry_.has_contour && controller_->has_target();
    if (std::optional<Point> expected = controller_->expected_pixel(at_capture)) {
        if (coasting) tracker_->reacquire_at(*expected);  // look again where the target should be by now
        else tracker_->predict_next(*expected);
    }
    const FrameResult& result = tracker_->process(frame_.image, frame_.chroma, deadline);
    const Contour& contour = tracker_->contour();
    if (result.has_contour && !controller_->consistent(contour.centroid, at_capture)) {
        tracker_->release();  // the contour ran off the target the controller follows: coast instead
        ++stats_.rejected_contours;
    }
    if (result.has_contour) {
        // A contour much smaller than the target has been is a partly hidden target, whose centre
        // lies off toward the visible part: it counts for less.
        if (!telemetry_.has_contour) {
            target_area_.reset();
            target_area_.update(contour.area);
        }
        const double shown = std::clamp(contour.area / std::max(target_area_.area(), 1.0), 0.0, 1.0);
        const double whole = target_area_.share();
        const double confidence = shown >= whole ? 1.0 : std::pow(shown / whole, 4.0);
        target_area_.update(contour.area);
        controller_->sighted(contour.centroid, at_capture, confidence);
        last_seen_at_ = at_capture;
        last_seen_pixel_ = contour.centroid;
        ++sighted_run_;
    } else {
        if (sighted_run_ > 0) run_before_gap_ = sighted_run_;
        sighted_run_ = 0;
    }
    const bool coasted_out = at_capture.t_s - last_seen_at_.t_s > tunables_.control.coast_s;
    if (!result.has_contour && controller_->has_target() &&
        (result.off_target || !controller_->expected_pixel(at_capture) || !controller_->can_coast() ||
         run_before_gap_ < kCoastRun || coasted_out)) {
        // A target the controller cannot predict, or not trust to (its estimate not settled, or the
        // target seen only briefly before this gap), is lost at once; a predicted one after coast_s.
        // One the tracker found it was not on (background) is lost at once too: the controller
        // followed the background, and its prediction would lead back there.
        controller_->lost();
        // A prediction followed for coast_s without finding the target again led nowhere (a
        // contour that crept along with the unit's own motion can lead it far): back to where the
        // target was last seen.
        if (!result.off_target && coasted_out) {
            const control::WorldAngles seen =
                camera.world_angles(last_seen_pixel_, last_seen_at_.pan, last_seen_at_.tilt);
            lost_policy_.lost_after_coasting(at_capture.t_s, seen.azimuth, seen.elevation);
        } else
            lost_policy_.lost_at(at_capture.t_s, at_capture.pan, at_capture.tilt);
    }
    telemetry_.frame = frame_.index;
    telemetry_.time_s = Seconds(frame_.stamp - started_).count();
    telemetry_.state = result.state;
    telemetry_.has_contour = result.has_contour;
    telemetry_.ref_x = result.has_contour ? static_cast<float>(contour.centroid.x) : 0.0f;
    telemetry_.ref_y = result.has_contour ? static_cast<float>(contour.centroid.y) : 0.0f;
    telemetry_.area_px = result.has_contour ? static_cast<float>(contour.area) : 0.0f;
    telemetry_.rays = result.has_contour ? contour.size : 0;
    telemetry_.levels = result.has_contour ? contour.levels : 0;
    telemetry_.deadline_hit = result.has_contour && contour.deadline_hit;
    telemetry_.psr = result.has_contour ? static_cast<float>(result.match_psr) : 0.0f;
    telemetry_.track_us = Micros(clock_.now() - begin).count();
    ++stats_.frames;
    if (telemetry_.deadline_hit) ++stats_.deadline_hits;
}

ptu::PtuCommand FrameLoop::next_command(TimePoint now) const {
    if (!driver_status_.ok) return ptu::PtuCommand::stop();
    if (require_homing_ && !(unit_.axes[0].homed && unit_.axes[1].homed))
        return ptu::PtuCommand::stop();  // the driver's own homing moves the axes meanwhile
    if (mode_ == ControlMode::Manual) {  // a person steers, camera or not
        if (jogging_ && now > jog_expires_) return ptu::PtuCommand::stop();
        return manual_;
    }
    if (!camera_was_connected_ || now - last_frame_at_ > frame_timeout_) return ptu::PtuCommand::stop();
    // While coasting the controller follows its prediction; once it has let go, the lost policy.
    if (!telemetry_.has_contour && !controller_->has_target()) return lost_policy_.command(seconds(now));
    return controller_->command(unit_pose(now));
}

void FrameLoop::drive_unit(TimePoint now) {
    commanded_ = next_command(now);
    ptu::DriverStatus wrote = ptu_.write(commanded_, now);
    ptu::DriverStatus got = ptu_.read(unit_, now);
    if (got.ok) pose_history_.record(control::UnitPose::of(unit_, seconds(unit_.stamp)));
    bool ok = wrote.ok && got.ok;
    if (!ok) {
        ++stats_.driver_errors;
        if (driver_status_.ok)
            channels_.log.log(Priority::Err, "PTU driver fault, axes stopped: %s", wrote.ok ? got.what() : wrote.what());
        driver_status_ = wrote.ok ? got : wrote;
    } else if (!driver_status_.ok) {
        channels_.log.log(Priority::Notice, "PTU driver recovered");
        driver_status_ = ptu::DriverStatus::success();
    }
    if (jogging_ && now > jog_expires_) {
        jogging_ = false;
        manual_ = ptu::PtuCommand::stop();
    }
}

void FrameLoop::record_times(float loop_us) {
    auto slot = static_cast<std::size_t>(stats_.frames % kRecentFrames);
    stats_.recent_loop_us[slot] = loop_us;
    stats_.recent_track_us[slot] = telemetry_.track_us;
    stats_.recent_latency_us[slot] = telemetry_.latency_us;
    auto bin = std::upper_bound(kHistogramEdgesUs.begin(), kHistogramEdgesUs.end(), loop_us);
    ++stats_.loop_histogram[static_cast<std::size_t>(
        std::min<std::ptrdiff_t>(bin - kHistogramEdgesUs.begin(), kHistogramBins - 1))];
}

void FrameLoop::publish(TimePoint now, TimePoint step_start) {
    telemetry_.mode = mode_;
    telemetry_.pan_deg = static_cast<float>(unit_.axes[0].position_rad * kDegPerRad);
    telemetry_.tilt_deg = static_cast<float>(unit_.axes[1].position_rad * kDegPerRad);
    telemetry_.pan_cmd_deg_s = velocity_deg_s(commanded_.axes[0]);
    telemetry_.tilt_cmd_deg_s = velocity_deg_s(commanded_.axes[1]);
    if (frame_fresh_) {
        telemetry_.loop_us = Micros(now - step_start).count();
        telemetry_.latency_us = Micros(now - frame_.stamp).count();
        record_times(telemetry_.loop_us);
        if (!channels_.telemetry.push(telemetry_)) ++stats_.telemetry_dropped;
        if (observer_ != nullptr) observer_->on_frame(telemetry_);
        channels_.snapshot.try_publish([&](SnapshotFrame& snap) {
            const Contour& contour = tracker_->contour();
            snap.frame = frame_.index;
            snap.image = frame_.image;
            snap.chroma = frame_.chroma;
            snap.has_contour = telemetry_.has_contour;
            snap.ref = contour.ref;
            snap.points = telemetry_.has_contour ? std::min(contour.size, kMaxSnapshotPoints) : 0;
            for (int i = 0; i < snap.points; ++i) snap.contour[static_cast<std::size_t>(i)] = contour.points[i].p;
        });
    }
    channels_.status.try_publish([&](LoopStatus& status) {
        status.last = telemetry_;
        status.running = true;
        status.camera_connected = camera_was_connected_;
        status.mode = mode_;
        status.ptu_fault = !driver_status_.ok;
        status.ptu_message = driver_status_.message;
        status.ptu = unit_;
        status.stats = stats_;
    });
    channels_.wake_socket_thread();
}

void FrameLoop::stop_unit() {
    if (tunables_.ptu.park_on_exit && driver_status_.ok) {
        ptu::PtuCommand park =
            position_command(tunables_.ptu.park_pan_deg * kRadPerDeg, tunables_.ptu.park_tilt_deg * kRadPerDeg);
        TimePoint give_up = clock_.now() + std::chrono::seconds(5);
        for (int tries = 0; tries < 1000 && clock_.now() < give_up; ++tries) {
            TimePoint now = clock_.now();
            if (!ptu_.write(park, now).ok || !ptu_.read(unit_, now).ok) break;
            bool arrived = std::abs(unit_.axes[0].position_rad - park.axes[0].value) < 1e-3 &&
                           std::abs(unit_.axes[1].position_rad - park.axes[1].value) < 1e-3;
            if (arrived) break;
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    }
    ptu_.stop(clock_.now());
    ptu_.deactivate();
}

}  // namespace rays::daemon
