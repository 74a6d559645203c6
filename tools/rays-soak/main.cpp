// rays-soak: the closed loop (simulated pan/tilt camera, raysd's frame loop, mock unit) run headless
// faster than real time, judged against the simulator's ground truth. See soak_metrics.hpp for the
// rules and README.md for the figures.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "closed_loop.hpp"
#include "daemon/daemon_params.hpp"
#include "soak_metrics.hpp"
#include "soak_options.hpp"
#include "soak_plot.hpp"

namespace {

using namespace rays;
using namespace rays::soak;

nlohmann::json summary_json(const SoakSummary& s) {
    nlohmann::json reacquire = nlohmann::json::array();
    for (const Loss& loss : s.losses) reacquire.push_back(loss.reacquire_s);
    return {{"frames", s.frames},
            {"acquired_s", s.acquired_s},
            {"losses", s.losses.size()},
            {"centred_fraction", s.centred_fraction},
            {"on_target_fraction", s.on_target_fraction},
            {"max_speed_deg_s", s.max_speed_deg_s},
            {"max_speed_px_frame", s.max_speed_px_frame},
            {"reacquire_s", reacquire},
            {"latency_us_median", s.latency_median_us},
            {"latency_us_p99", s.latency_p99_us},
            {"pan_range_deg", {s.pan_min_deg, s.pan_max_deg}},
            {"tilt_range_deg", {s.tilt_min_deg, s.tilt_max_deg}},
            {"max_rate_deg_s", {s.max_abs_pan_rate_deg_s, s.max_abs_tilt_rate_deg_s}}};
}

nlohmann::json setup_json(const daemon::DaemonConfig& c, long frames) {
    return {{"scenario", c.sim.scenario}, {"seed", c.sim.seed},        {"fps", c.sim.fps},
            {"frames", frames},           {"method", c.tracker.method == TrackerMethod::Snake ? "snake" : "rays"},
            {"law", c.control.law},       {"gain", c.control.gain},    {"budget_ms", c.loop.budget_ms},
            {"rays", c.tracker.tunables.rays.count}, {"hypotheses", c.tracker.tunables.rays.hypotheses},
            {"max_velocity_deg_s", c.ptu.motion.max_velocity_deg_s},
            {"max_accel_deg_s2", c.ptu.motion.max_accel_deg_s2}};
}

void print_summary(const daemon::DaemonConfig& c, const SoakSummary& s) {
    std::printf("rays-soak: scenario %s seed %d, %ld frames at %g fps; tracker %s, control %s gain %g/s, budget %g ms\n",
                c.sim.scenario.c_str(), c.sim.seed, s.frames, c.sim.fps,
                c.tracker.method == TrackerMethod::Snake ? "snake" : "rays", c.control.law.c_str(), c.control.gain,
                c.loop.budget_ms);
    std::printf("  acquired at %.2f s; losses %zu, centred %.1f %%, contour on target %.1f %%\n", s.acquired_s,
                s.losses.size(), 100 * s.centred_fraction, 100 * s.on_target_fraction);
    std::printf("  fastest target kept: %.1f deg/s (%.2f px/frame)\n", s.max_speed_deg_s, s.max_speed_px_frame);
    for (const Loss& loss : s.losses) {
        if (loss.reacquire_s < 0) std::printf("  lost at %.2f s, not re-acquired\n", loss.start_s);
        else std::printf("  lost at %.2f s, re-acquired after %.2f s\n", loss.start_s, loss.reacquire_s);
    }
    std::printf("  loop latency (capture to PTU write): median %.0f us, p99 %.0f us\n", s.latency_median_us,
                s.latency_p99_us);
    std::printf("  unit: pan %.1f..%.1f deg, tilt %.1f..%.1f deg, fastest %.1f / %.1f deg/s (limit %g)\n",
                s.pan_min_deg, s.pan_max_deg, s.tilt_min_deg, s.tilt_max_deg, s.max_abs_pan_rate_deg_s,
                s.max_abs_tilt_rate_deg_s, c.ptu.motion.max_velocity_deg_s);
}

}  // namespace

int main(int argc, char** argv) {
    SoakOptions options;
    if (std::optional<std::string> problem = parse_options(argc, argv, options)) {
        std::fprintf(stderr, "rays-soak: %s\n%s\n", problem->c_str(), kUsage);
        return 2;
    }
    if (options.help) {
        std::printf("%s\n", kUsage);
        return 0;
    }
    SoakRun run;
    run.frames = options.frames;
    run.overlay_dir = options.overlay_dir;
    run.overlay_from_s = options.overlay_from_s;
    run.overlay_to_s = options.overlay_to_s;
    if (!options.config_path.empty()) {
        if (auto problem = daemon::load_daemon_config(options.config_path, run.config)) {
            std::fprintf(stderr, "rays-soak: %s\n", problem->to_string().c_str());
            return 2;
        }
    }
    run.config.sim.scenario = options.scenario;
    if (options.seed) run.config.sim.seed = *options.seed;
    if (options.law) run.config.control.law = *options.law;
    if (options.method) run.config.tracker.method = *options.method == "snake" ? TrackerMethod::Snake : TrackerMethod::Rays;
    if (options.gain) run.config.control.gain = *options.gain;
    if (options.budget_ms) run.config.loop.budget_ms = *options.budget_ms;

    std::vector<double> gains = options.sweep_gains;
    if (gains.empty()) gains.push_back(run.config.control.gain);
    nlohmann::json sweep = nlohmann::json::array();
    double best_gain = gains.front(), best_speed = -1;
    for (double gain : gains) {
        run.config.control.gain = gain;
        std::string error;
        std::vector<SoakFrame> frames = run_closed_loop(run, error);
        if (frames.empty()) {
            std::fprintf(stderr, "rays-soak: %s\n", error.c_str());
            return 1;
        }
        SoakSummary summary = summarise(frames);
        if (summary.max_speed_deg_s > best_speed) {
            best_speed = summary.max_speed_deg_s;
            best_gain = gain;
        }
        if (!options.json) print_summary(run.config, summary);
        nlohmann::json row = summary_json(summary);
        row["config"] = setup_json(run.config, run.frames);
        sweep.push_back(row);
        if (!options.plot_path.empty() && gains.size() == 1 && !write_plot(options.plot_path, frames, error)) {
            std::fprintf(stderr, "rays-soak: plot %s: %s\n", options.plot_path.c_str(), error.c_str());
            return 1;
        }
        if (!options.trace_path.empty() && gains.size() == 1 && !write_trace(options.trace_path, frames, error)) {
            std::fprintf(stderr, "rays-soak: trace %s: %s\n", options.trace_path.c_str(), error.c_str());
            return 1;
        }
    }
    if (gains.size() > 1 && !options.json)
        std::printf("best gain for the fastest target kept: %g/s (%.1f deg/s)\n", best_gain, best_speed);
    if (options.json) {
        nlohmann::json out = gains.size() == 1 ? sweep.front() : nlohmann::json{{"sweep", sweep}, {"best_gain", best_gain}};
        std::printf("%s\n", out.dump().c_str());
    }
    return 0;
}
