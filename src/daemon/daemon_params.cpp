// SPDX-License-Identifier: Apache-2.0
// Every key of raysd.ini beyond the tracking core's ([rays], [detect], [attention], [track]):
// [camera], [loop], [control], [ptu], [mock], [socket], [log]. Defaults are the member
// initialisers in daemon_config.hpp.
#include "daemon/daemon_params.hpp"

#include "sim/exposure_delay.hpp"

#include "config/config_engine.hpp"
#include "config/config_table.hpp"
#include "drivers/can/canopen/canopen_settings.hpp"
#include "drivers/can/odrive/odrive_settings.hpp"
#include "drivers/gpio/gpio_params.hpp"
#include "drivers/gpio/pwm_params.hpp"
#include "drivers/modbus/modbus_settings.hpp"

namespace rays::daemon {
namespace {

using config::ParamKind;
using config::ParamTable;

void add_camera(ParamTable<DaemonConfig>& table) {
    table.section("camera", ParamKind::Capacity, &DaemonConfig::camera)
        .add_choice("source", &CameraSettings::source, "sim|v4l2|replay",
                    "where frames come from: the simulated pan/tilt camera ([sim]), a V4L2 camera or a recorded sequence")
        .add("device", &CameraSettings::device, "v4l2: the video device node")
        .add_choice("format", &CameraSettings::format, "auto|grey|yuyv|mjpeg",
                    "v4l2: pixel format (auto prefers grey, then yuyv, then mjpeg)")
        .add("width", &CameraSettings::width, "px", 16, 8192, "v4l2: requested width (the driver may grant another)")
        .add("height", &CameraSettings::height, "px", 16, 8192, "v4l2: requested height")
        .add("fps", &CameraSettings::fps, "1/s", 1, 1000, "v4l2: requested frame rate")
        .add("crop_x", &CameraSettings::crop_x, "px", 0, 8192, "left edge of the crop of the source frame")
        .add("crop_y", &CameraSettings::crop_y, "px", 0, 8192, "top edge of the crop")
        .add("crop_w", &CameraSettings::crop_w, "px", 0, 8192, "crop width, 0: the whole frame (no crop)")
        .add("crop_h", &CameraSettings::crop_h, "px", 0, 8192, "crop height, 0 with crop_w = 0")
        .add("replay_path", &CameraSettings::replay_path,
             "replay: a YUV4MPEG2 file, FIFO or - (standard input), or a folder of PGM/PNG frames")
        .add("replay_paced", &CameraSettings::replay_paced,
             "replay: deliver frames at the sequence's frame rate (false: as fast as they are tracked)")
        .add("replay_loop", &CameraSettings::replay_loop, "replay: start again at the end (not for FIFOs or stdin)")
        .add("frame_timeout_s", &CameraSettings::frame_timeout_s, "s", 0.01, 60,
             "the frame loop wakes (and feeds the watchdog) this often while no frame comes")
        .add("queue_frames", &CameraSettings::queue_frames, "frames", 2, 64,
             "frames buffered between capture and tracking; a live camera drops the oldest when full");
}

void add_sim(ParamTable<DaemonConfig>& table) {
    table.section("sim", ParamKind::Capacity, &DaemonConfig::sim)
        .add_choice("scenario", &SimSettings::scenario, "soak|soak-clutter|patrol|ramp|crowd|horizon",
                    "what the simulated camera sees: the 30-minute soak path against the sky or through "
                    "buildings, a walker on patrol, a target speeding up, several targets")
        .add("seed", &SimSettings::seed, "", 0, 1000000, "seed of the simulated world and its noise")
        .add("fps", &SimSettings::fps, "1/s", 1, 200, "frames per second the simulated camera delivers")
        .add("panorama_png", &SimSettings::panorama_png,
             "the world as an equirectangular PNG (its width spans 360 degrees); empty: generated from the seed")
        .add("latency_frames", &SimSettings::latency_frames, "frames", 0, sim::ExposureDelay::kMaxFrames,
             "camera latency: each frame shows the world and the unit as they were this many frame periods "
             "before it is delivered")
        .add("stamp_exposure", &SimSettings::stamp_exposure,
             "stamp each frame with its exposure time, as V4L2 cameras do; false: with its delivery time "
             "(a camera that does not time-stamp its exposures, whose latency the loop cannot see)");
}

void add_loop(ParamTable<DaemonConfig>& table) {
    table.section("loop", ParamKind::Tunable, &DaemonConfig::loop)
        .add("budget_ms", &LoopSettings::budget_ms, "ms", 0.05, 1000,
             "tracking deadline after the frame reached raysd; refinement stops there (any-time)");
    table.section("loop", ParamKind::Capacity, &DaemonConfig::loop)
        .add("rt_priority", &LoopSettings::rt_priority, "", 0, 99,
             "SCHED_FIFO priority of the frame loop, 0: normal scheduling")
        .add("cpu", &LoopSettings::cpu, "", -1, 1023, "pin the frame loop to this CPU, -1: any CPU")
        .add("lock_memory", &LoopSettings::lock_memory, "lock all memory in RAM (mlockall) so no page fault stalls a frame");
}

void add_control(ParamTable<DaemonConfig>& table) {
    table.section("control", ParamKind::Tunable, &DaemonConfig::control)
        .add_choice("law", &ControlSettings::law, "predictive|proportional",
                    "predictive: Kalman filter on the target's world angles, velocity feed-forward, and the "
                    "tracker's next reference point predicted; proportional: the paper's controller")
        .add("horizontal_fov_deg", &ControlSettings::horizontal_fov_deg, "deg", 1, 170,
             "field of view across the processed frame's width (after any crop)")
        .add("vertical_fov_deg", &ControlSettings::vertical_fov_deg, "deg", 1, 170,
             "field of view across the processed frame's height")
        .add("fx_px", &ControlSettings::fx_px, "px", 0, 100000,
             "calibrated focal length across, in processed pixels; 0: from horizontal_fov_deg and vertical_fov_deg")
        .add("fy_px", &ControlSettings::fy_px, "px", 0, 100000, "calibrated focal length down, in processed pixels")
        .add("cx_px", &ControlSettings::cx_px, "px", -1000, 1000, "calibrated principal point x (with fx_px)")
        .add("cy_px", &ControlSettings::cy_px, "px", -1000, 1000, "calibrated principal point y (with fx_px)")
        .add("gain", &ControlSettings::gain, "1/s", 0, 50, "velocity command per angular error")
        .add("deadband_deg", &ControlSettings::deadband_deg, "deg", 0, 20,
             "angular errors smaller than this command zero velocity on that axis (predictive: when the "
             "target is also still)")
        .add("lead_ms", &ControlSettings::lead_ms, "ms", 0, 1000,
             "predictive: aim where target and unit will be this much later, beyond the unit's own latency")
        .add_choice("target_motion", &ControlSettings::target_motion, "velocity|acceleration",
                    "predictive: the Kalman filter's motion model: constant velocity, or constant acceleration "
                    "(for targets that swing and turn hard, seen with camera latency)")
        .add("target_accel_deg_s2", &ControlSettings::target_accel_deg_s2, "deg/s^2", 0.01, 100000,
             "predictive, velocity model: how hard targets accelerate (the Kalman filter's process noise)")
        .add("target_jerk_deg_s3", &ControlSettings::target_jerk_deg_s3, "deg/s^3", 0.01, 1000000,
             "predictive, acceleration model: how fast targets change their acceleration (process noise)")
        .add("sighting_noise_px", &ControlSettings::sighting_noise_px, "px", 0.01, 100,
             "predictive: 1 sigma of the contour centre's position (the Kalman filter's measurement noise)")
        .add("still_deg_s", &ControlSettings::still_deg_s, "deg/s", 0, 100,
             "the unit counts as still below this rate: frame differencing finds new targets only then")
        .add("coast_s", &ControlSettings::coast_s, "s", 0, 60,
             "predictive: after losing the contour, follow the prediction and look for the target where it "
             "should be for this long (only a target seen 10 frames in a row before: otherwise stop at once)")
        .add_choice("lost_action", &ControlSettings::lost_action, "hold|search|home",
                    "with no target for lost_timeout_s: keep holding still, search left and right, or go home (after coast_s on a prediction that found nothing, first back to where the target was last seen)")
        .add("lost_timeout_s", &ControlSettings::lost_timeout_s, "s", 0, 3600,
             "the unit holds still this long after losing the target (detection needs a still camera)")
        .add("search_step_deg", &ControlSettings::search_step_deg, "deg", 0.1, 180, "search: pan step between poses")
        .add("search_steps", &ControlSettings::search_steps, "", 1, 50,
             "search: poses on each side of where the target was lost")
        .add("search_dwell_s", &ControlSettings::search_dwell_s, "s", 0.1, 600,
             "search: time at each pose, moving there included");
}

void add_ptu(ParamTable<DaemonConfig>& table) {
    table.section("ptu", ParamKind::Capacity, &DaemonConfig::ptu)
        .add_choice("driver", &PtuSettings::driver, "mock|modbus|canopen|odrive|gpio-stepper|pwm-servo",
                    "pan/tilt unit driver, configured in its section: [mock], [modbus], [canopen], [odrive], [gpio] (gpio-stepper) or [pwm] (pwm-servo)")
        .add("pan_inverted", &PtuSettings::pan_inverted, "the unit's pan axis turns left for positive angles")
        .add("tilt_inverted", &PtuSettings::tilt_inverted, "the unit's tilt axis turns down for positive angles")
        .add("pan_zero_deg", &PtuSettings::pan_zero_deg, "deg", -360, 360,
             "the unit's pan angle when the rig looks straight ahead")
        .add("tilt_zero_deg", &PtuSettings::tilt_zero_deg, "deg", -180, 180,
             "the unit's tilt angle when the rig looks level")
        .add("require_homing", &PtuSettings::require_homing,
             "no motion until the unit reports both axes homed ('raysctl ptu home')");
    table.section("ptu", ParamKind::Tunable, [](DaemonConfig& config) -> auto& { return config.ptu.motion; })
        .add("pan_min_deg", &PtuMotion::pan_min_deg, "deg", -360, 360, "soft limit: lowest pan angle")
        .add("pan_max_deg", &PtuMotion::pan_max_deg, "deg", -360, 360, "soft limit: highest pan angle")
        .add("tilt_min_deg", &PtuMotion::tilt_min_deg, "deg", -180, 180, "soft limit: lowest tilt angle")
        .add("tilt_max_deg", &PtuMotion::tilt_max_deg, "deg", -180, 180, "soft limit: highest tilt angle")
        .add("max_velocity_deg_s", &PtuMotion::max_velocity_deg_s, "deg/s", 0.1, 1000,
             "fastest commanded axis velocity")
        .add("max_accel_deg_s2", &PtuMotion::max_accel_deg_s2, "deg/s^2", 0.1, 100000,
             "largest commanded change of axis velocity per second")
        .add("command_timeout_s", &PtuMotion::command_timeout_s, "s", 0.05, 10,
             "a manual jog stops when not renewed within this")
        .add("home_pan_deg", &PtuMotion::home_pan_deg, "deg", -360, 360, "pan angle of 'ptu home'")
        .add("home_tilt_deg", &PtuMotion::home_tilt_deg, "deg", -180, 180, "tilt angle of 'ptu home'")
        .add("park_pan_deg", &PtuMotion::park_pan_deg, "deg", -360, 360, "pan angle of 'ptu park'")
        .add("park_tilt_deg", &PtuMotion::park_tilt_deg, "deg", -180, 180, "tilt angle of 'ptu park'")
        .add("park_on_exit", &PtuMotion::park_on_exit, "park the unit before stopping on SIGTERM");
}

void add_mock(ParamTable<DaemonConfig>& table) {
    table.section("mock", ParamKind::Capacity, &DaemonConfig::mock)
        .add("max_velocity_deg_s", &MockPtuSettings::max_velocity_deg_s, "deg/s", 0.1, 1000,
             "the simulated unit's fastest axis velocity")
        .add("max_accel_deg_s2", &MockPtuSettings::max_accel_deg_s2, "deg/s^2", 0.1, 100000,
             "the simulated unit's largest acceleration")
        .add("latency_ms", &MockPtuSettings::latency_ms, "ms", 0, 1000,
             "delay before the simulated unit acts on a command")
        .add("record_path", &MockPtuSettings::record_path,
             "when set, every command the simulated unit received is written to this CSV file at exit");
}

void add_socket(ParamTable<DaemonConfig>& table) {
    table.section("socket", ParamKind::Capacity, &DaemonConfig::socket)
        .add("path", &SocketSettings::path,
             "command socket (Unix stream, mode 0660); a relative path is taken from the working directory")
        .add("max_clients", &SocketSettings::max_clients, "", 1, 256, "most clients connected at once")
        .add("max_line_bytes", &SocketSettings::max_line_bytes, "bytes", 256, 1048576, "longest request line")
        .add("max_output_kib", &SocketSettings::max_output_kib, "KiB", 16, 65536,
             "a client with more unsent replies than this is disconnected (a watch client that does not read)");
}

void add_log(ParamTable<DaemonConfig>& table) {
    table.section("log", ParamKind::Tunable, &DaemonConfig::log)
        .add_choice("level", &LogSettings::level, "debug|info|notice|warning|err", "least important message logged")
        .add("repeat_interval_s", &LogSettings::repeat_interval_s, "s", 0, 3600,
             "a message repeated within this is logged once, with the count of repeats");
}

ParamTable<DaemonConfig> build_daemon_params() {
    ParamTable<DaemonConfig> table;
    add_camera(table);
    add_sim(table);
    table.include(config::tracker_params(), &DaemonConfig::tracker);
    add_loop(table);
    add_control(table);
    add_ptu(table);
    add_mock(table);
    table.include(ptu::modbus_params(), &DaemonConfig::modbus);
    table.include(canopen::canopen_params(), &DaemonConfig::canopen);
    table.include(odrive::odrive_params(), &DaemonConfig::odrive);
    table.include(gpio::gpio_params(), &DaemonConfig::gpio);
    table.include(gpio::pwm_params(), &DaemonConfig::pwm);
    add_socket(table);
    add_log(table);
    table.add_rule(config::less_than("ptu.pan_min_deg", "ptu.pan_max_deg"));
    table.add_rule(config::less_than("ptu.tilt_min_deg", "ptu.tilt_max_deg"));
    return table;
}

}  // namespace

const config::ParamTable<DaemonConfig>& daemon_params() {
    static const config::ParamTable<DaemonConfig> table = build_daemon_params();
    return table;
}

std::optional<config::ConfigError> load_daemon_config(const std::string& path, DaemonConfig& out) {
    return config::load_ini(path, daemon_params(), out);
}

std::string changed_capacities(const DaemonConfig& a, const DaemonConfig& b) {
    std::string names;
    for (const config::Param<DaemonConfig>& param : daemon_params().params()) {
        if (param.info.kind != ParamKind::Capacity || param.read(a) == param.read(b)) continue;
        if (!names.empty()) names += ", ";
        names += param.info.name;
    }
    return names;
}

DaemonConfig rig_template() {
    DaemonConfig config;
    config.camera.source = "v4l2";
    config.ptu.driver = "modbus";
    config.modbus.transport = "rtu";
    config.modbus.device = "/dev/ttyUSB0";
    config.modbus.preset = "uumotor-svd48v";
    return config;
}

void copy_tunables(const DaemonConfig& from, DaemonConfig& to) {
    for (const config::Param<DaemonConfig>& param : daemon_params().params())
        if (param.info.kind == ParamKind::Tunable) param.write(to, param.read(from));
}

}  // namespace rays::daemon
