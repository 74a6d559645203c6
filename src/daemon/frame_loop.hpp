// SPDX-License-Identifier: Apache-2.0
// The real-time frame loop: next frame (its only wait, with a timeout) → commands from the socket →
// track with deadline = capture time + budget → control → limited PTU write and state read →
// telemetry, status and snapshot out → watchdog. Nothing here allocates, blocks on I/O or throws
// once run() has started.
//
// Around the tracker: the controller predicts where the target will show in each frame (from the
// unit's pose at capture), and frame differencing may find a new target only when the unit stood
// still from the previous frame's capture to this one's (ego-motion). When the contour is lost, a
// predictive controller coasts on its prediction for control.coast_s, and the tracker is restarted
// where the target should be; after that, or at once without prediction, the lost policy holds,
// searches or goes home.
#pragma once
#include <chrono>
#include <memory>

#include "control/lost_policy.hpp"
#include "control/predictive_controller.hpp"
#include "control/pose_history.hpp"
#include "control/proportional_controller.hpp"
#include "core/clock.hpp"
#include "core/contour_tracker.hpp"
#include "core/whole_area.hpp"
#include "daemon/loop_channels.hpp"
#include "daemon/service_notifier.hpp"
#include "drivers/ptu_limiter.hpp"

namespace rays::daemon {

// Tests watch every processed frame through this; called on the frame loop's thread.
class FrameObserver {
public:
    virtual ~FrameObserver() = default;
    virtual void on_frame(const FrameTelemetry& frame) = 0;
};

class FrameLoop {
public:
    FrameLoop(const DaemonConfig& config, LoopChannels& channels, ptu::PtuLimiter& ptu, ServiceNotifier& notifier,
              const Clock& clock, FrameObserver* observer = nullptr);

    // Steps until channels.stop, then stops the unit (parking first when configured).
    void run();
    // One pass; public for tests that drive the loop by hand.
    void step();
    // Stops both axes, parking first when configured; bounded in time.
    void stop_unit();

private:
    void apply(const LoopCommand& command, TimePoint now);
    void apply_tunables(const LoopTunables& tunables);
    void track_frame(TimePoint now);
    ptu::PtuCommand next_command(TimePoint now) const;
    double seconds(TimePoint t) const;
    bool commands_motion() const;  // the last command written moves the unit (or has not arrived)
    control::UnitPose unit_pose(TimePoint t) const;  // the unit at t, from its reports (pose_history_)
    void set_controllers();
    void drive_unit(TimePoint now);
    void publish(TimePoint now, TimePoint step_start);
    void record_times(float loop_us);

    LoopChannels& channels_;
    ptu::PtuLimiter& ptu_;
    ServiceNotifier& notifier_;
    const Clock& clock_;
    FrameObserver* observer_;
    std::unique_ptr<ContourTracker> tracker_;
    LoopTunables tunables_;
    control::ProportionalController proportional_;
    control::PredictiveController predictive_;
    control::Controller* controller_;  // one of the two, by control.law
    control::LostPolicy lost_policy_;
    control::UnitPose last_seen_at_;  // the unit at the capture of the last frame with a contour
    Point last_seen_pixel_;           // ... and the contour's centre in that frame
    int sighted_run_ = 0;           // frames in a row with a contour, up to this one
    int run_before_gap_ = 0;        // ... and in the run the current gap ended
    WholeArea target_area_{0.85, 0.05};  // the tracked target's running area while whole in view, px²
    bool still_at_last_frame_ = false;
    std::optional<control::UnitPose> last_capture_;  // the unit at the last tracked frame's capture
    bool require_homing_;
    std::chrono::nanoseconds frame_timeout_;  // no frame for this long: the axes stop
    std::chrono::nanoseconds wait_;           // longest wait for a frame: the unit gets a write this often
    TimePoint started_;

    CapturedFrame frame_;
    bool frame_fresh_ = false;
    TimePoint last_frame_at_{};       // the axes stop when no frame came for frame_timeout_
    FrameTelemetry telemetry_;
    LoopStats stats_;
    ControlMode mode_ = ControlMode::Automatic;
    ptu::PtuCommand manual_;          // the manual command in force
    TimePoint jog_expires_{};         // a jog stops by itself after this
    bool jogging_ = false;
    ptu::PtuCommand commanded_;       // the last command written
    ptu::PtuState unit_;
    control::PoseHistory pose_history_;  // the unit's recent reports, for the pose at a frame's exposure
    ptu::DriverStatus driver_status_;
    bool camera_was_connected_ = true;
};

}  // namespace rays::daemon
