// SPDX-License-Identifier: Apache-2.0
// Everything raysd reads from its INI file: the tracking core's settings plus one struct per
// subsystem section. Defaults are the member initialisers; the table in daemon_params.cpp gives
// each key its unit, range and whether it is a capacity (fixed at start) or a tunable.
#pragma once
#include <string>

#include "core/tracker_config.hpp"
#include "drivers/can/canopen/canopen_settings.hpp"
#include "drivers/can/odrive/odrive_settings.hpp"
#include "drivers/gpio/gpio_settings.hpp"
#include "drivers/gpio/pwm_settings.hpp"
#include "drivers/modbus/modbus_settings.hpp"

namespace rays::daemon {

struct CameraSettings {                   // [camera]: fixed at start
    std::string source = "sim";           // sim | v4l2 | replay
    std::string device = "/dev/video0";   // V4L2 device node
    std::string format = "auto";          // auto | grey | yuyv | mjpeg
    int width = 640;                      // requested capture size; the driver may grant another
    int height = 480;
    int fps = 30;
    int crop_x = 0;                       // crop of the source frame before scaling; crop_w = 0: none
    int crop_y = 0;
    int crop_w = 0;
    int crop_h = 0;
    std::string replay_path;              // replay: YUV4MPEG2 file, FIFO, "-" (stdin) or image folder
    bool replay_paced = true;             // replay at the file's frame rate, else as fast as tracked
    bool replay_loop = false;             // start again at the end (files and folders only)
    double frame_timeout_s = 1.0;         // the frame loop wakes this often without frames
    int queue_frames = 4;                 // frames buffered between capture and the frame loop
};

struct SimSettings {                      // [sim]: the simulated camera, fixed at start
    std::string scenario = "soak";        // soak | soak-clutter | patrol | ramp | crowd
    int seed = 1;                         // the world's and the noise's seed
    double fps = 25.0;                    // frames per second rendered (paced in real time)
    std::string panorama_png;             // the world as an equirectangular PNG; empty: generated from the seed
    int latency_frames = 0;               // frames from exposure to delivery
    bool stamp_exposure = true;           // stamped at exposure (as V4L2 does), else at delivery
};

struct LoopSettings {                 // [loop]
    double budget_ms = 20.0;          // tunable: tracking deadline after the frame reached raysd
    int rt_priority = 0;              // SCHED_FIFO priority of the frame loop, 0: normal scheduling
    int cpu = -1;                     // pin the frame loop to this CPU, -1: any
    bool lock_memory = false;         // mlockall(MCL_CURRENT | MCL_FUTURE)
};

struct ControlSettings {                 // [control]: tunables
    std::string law = "predictive";      // proportional | predictive
    double horizontal_fov_deg = 60.0;    // camera field of view across the 128-pixel frame width
    double vertical_fov_deg = 60.0;      // ... and height (after any crop)
    double fx_px = 0.0;                  // calibrated intrinsics in processing pixels; fx_px = 0: from the FOV
    double fy_px = 0.0;
    double cx_px = 63.5;
    double cy_px = 63.5;
    double gain = 4.0;                   // rad/s per rad of angular error
    double deadband_deg = 0.3;           // errors smaller than this command zero velocity
    double lead_ms = 20.0;               // predictive: aim this far ahead, beyond the unit's own latency
    std::string target_motion = "velocity";  // predictive: the filter's model, velocity | acceleration
    double target_accel_deg_s2 = 60.0;   // predictive, velocity model: how hard targets accelerate (Kalman process noise)
    double target_jerk_deg_s3 = 2000.0;  // predictive, acceleration model: how fast their acceleration changes
    double sighting_noise_px = 0.7;      // predictive: 1 σ of the contour centre's position
    double still_deg_s = 0.3;            // the unit counts as still below this rate (frame differencing runs only then)
    double coast_s = 1.0;                // predictive: follow the prediction this long after losing the contour
    std::string lost_action = "hold";    // hold | search | home, after lost_timeout_s without a target
    double lost_timeout_s = 3.0;
    double search_step_deg = 20.0;       // search: pan step between poses
    int search_steps = 3;                // search: poses on each side of where the target was lost
    double search_dwell_s = 1.5;         // search: time at each pose
};

struct PtuMotion {                       // [ptu] tunables: limits enforced above every driver, and poses
    double pan_min_deg = -170.0;         // soft angle limits
    double pan_max_deg = 170.0;
    double tilt_min_deg = -30.0;
    double tilt_max_deg = 90.0;
    double max_velocity_deg_s = 90.0;
    double max_accel_deg_s2 = 360.0;
    double command_timeout_s = 0.5;      // a manual jog ends when not renewed within this
    double home_pan_deg = 0.0;
    double home_tilt_deg = 0.0;
    double park_pan_deg = 0.0;
    double park_tilt_deg = -30.0;
    bool park_on_exit = false;           // park before stopping on SIGTERM
};

struct PtuSettings {                     // [ptu]
    std::string driver = "mock";         // fixed at start: mock | modbus | canopen | odrive | gpio-stepper | pwm-servo
    bool pan_inverted = false;           // fixed at start: the unit's axis turns the other way
    bool tilt_inverted = false;
    double pan_zero_deg = 0.0;           // fixed at start: the unit's angle where the rig's is 0
    double tilt_zero_deg = 0.0;
    bool require_homing = false;         // fixed at start: no motion until the unit reports homed
    PtuMotion motion;
};

struct MockPtuSettings {                 // [mock]: the simulated unit's dynamics, fixed at start
    double max_velocity_deg_s = 120.0;
    double max_accel_deg_s2 = 720.0;
    double latency_ms = 10.0;
    std::string record_path;  // when set, every command the unit received is written here (CSV) at exit
};

struct SocketSettings {                       // [socket]: fixed at start
    std::string path = "/run/raysd/raysd.sock";
    int max_clients = 16;
    int max_line_bytes = 4096;                // longest request line
    int max_output_kib = 256;                 // a client's unsent replies beyond this: dropped
};

struct LogSettings {                    // [log]
    std::string level = "info";         // tunable: debug | info | notice | warning | err
    double repeat_interval_s = 10.0;    // tunable: one line per message and interval; repeats counted
};

struct DaemonConfig {
    TrackerConfig tracker;
    CameraSettings camera;
    SimSettings sim;
    LoopSettings loop;
    ControlSettings control;
    PtuSettings ptu;
    MockPtuSettings mock;
    ptu::ModbusSettings modbus;
    canopen::CanopenSettings canopen;
    odrive::OdriveSettings odrive;
    gpio::GpioSettings gpio;
    gpio::PwmSettings pwm;
    SocketSettings socket;
    LogSettings log;
};

}  // namespace rays::daemon
