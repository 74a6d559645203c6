// SPDX-License-Identifier: Apache-2.0
// What crosses between the socket thread and the frame loop, all fixed-size and trivially copyable:
// commands in (through an SpscRing), per-frame telemetry out (SpscRing, for `watch`), and the
// newest status, statistics and snapshot frame out (LatestValue).
#pragma once
#include <array>
#include <cstdint>

#include "core/box.hpp"
#include "core/clock.hpp"
#include "core/image.hpp"
#include "core/contour_tracker.hpp"
#include "daemon/control_tunables.hpp"
#include "daemon/daemon_config.hpp"
#include "drivers/ptu_driver.hpp"

namespace rays::daemon {

// Everything the frame loop may change at run time.
struct LoopTunables {
    TrackerTunables tracker;
    double budget_ms = 20.0;
    ControlTunables control;
    PtuMotion ptu;
};
LoopTunables loop_tunables(const DaemonConfig& config);

// Track: a point start; TrackBox: a box start (core/box.hpp).
enum class CommandKind { Tunables, Track, TrackBox, Release, Reinit, Jog, Goto, Stop, Home, Park, Resume };

struct LoopCommand {
    CommandKind kind = CommandKind::Stop;
    double a = 0.0;  // Track: x px; Jog: pan rad/s; Goto: pan rad
    double b = 0.0;  // Track: y px; Jog: tilt rad/s; Goto: tilt rad
    Box box;         // TrackBox only, processing pixels
    LoopTunables tunables;  // Tunables only
};

inline LoopCommand make_command(CommandKind kind, double a = 0.0, double b = 0.0) {
    LoopCommand command;
    command.kind = kind;
    command.a = a;
    command.b = b;
    return command;
}

inline LoopCommand make_box_command(const Box& box) {
    LoopCommand command = make_command(CommandKind::TrackBox);
    command.box = box;
    return command;
}

// Who moves the unit: the tracker, or a person through `ptu` (until `track` or `resume`).
enum class ControlMode { Automatic, Manual };
const char* to_string(ControlMode mode);

struct FrameTelemetry {
    long frame = -1;            // the source's frame index
    double time_s = 0.0;        // capture time, seconds since the daemon started
    TrackState state = TrackState::Detecting;
    bool has_contour = false;
    float ref_x = 0, ref_y = 0;  // reference point m (processing pixels)
    float area_px = 0;
    int rays = 0, levels = 0;
    bool deadline_hit = false;
    float psr = 0;              // how surely the target's looks were found (FrameResult::match_psr)
    float track_us = 0;         // tracking (smoothing, detection, extraction)
    float loop_us = 0;          // the whole frame loop step, capture hand-over to driver write
    float latency_us = 0;       // capture time to driver write
    ControlMode mode = ControlMode::Automatic;
    float pan_deg = 0, tilt_deg = 0;          // the unit's reported angles
    float pan_cmd_deg_s = 0, tilt_cmd_deg_s = 0;  // velocity commanded (0 in position moves)
};

constexpr int kRecentFrames = 1024;  // window for median and p99
constexpr int kHistogramBins = 16;   // loop time: bin i holds times below kHistogramEdgesUs[i]
inline constexpr std::array<float, kHistogramBins> kHistogramEdgesUs = {
    50, 100, 200, 300, 500, 750, 1000, 1500, 2000, 3000, 5000, 10000, 20000, 50000, 100000, 1e30f};

struct LoopStats {
    long frames = 0;             // frames tracked
    long deadline_hits = 0;      // frames whose refinement the deadline cut short
    long late_frames = 0;        // frames whose deadline had passed before tracking began
    long frame_timeouts = 0;     // loop passes without a frame (the loop wakes at least every 50 ms)
    long rejected_contours = 0;  // contours the controller's prediction ruled out (the tracker restarted)
    long driver_errors = 0;      // failed driver writes or reads
    long telemetry_dropped = 0;  // watch records the socket thread did not take in time
    std::array<long, kHistogramBins> loop_histogram{};
    std::array<float, kRecentFrames> recent_loop_us{};
    std::array<float, kRecentFrames> recent_track_us{};
    std::array<float, kRecentFrames> recent_latency_us{};
};

struct LoopStatus {
    FrameTelemetry last;
    bool running = false;
    bool camera_connected = false;
    ControlMode mode = ControlMode::Automatic;
    bool ptu_fault = false;
    std::array<char, 120> ptu_message{};  // the driver's last error, empty when none
    ptu::PtuState ptu;
    LoopStats stats;
};

constexpr int kMaxSnapshotPoints = 4096;  // the largest rays.max_rays allows

struct SnapshotFrame {
    long frame = -1;
    GreyImage image;
    Chroma chroma;  // present where the source has colour
    bool has_contour = false;
    Point ref;
    int points = 0;
    std::array<Point, kMaxSnapshotPoints> contour;
};

}  // namespace rays::daemon
