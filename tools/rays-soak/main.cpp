// SPDX-License-Identifier: Apache-2.0
// rays-soak: the closed loop (simulated pan/tilt camera, raysd's frame loop, mock unit) run headless
// faster than real time, judged against the simulator's ground truth. See soak_metrics.hpp for the
// rules and README.md for the figures.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "closed_loop.hpp"
#include "daemon/daemon_params.hpp"
#include "soak_metrics.hpp"
#include "soak_options.hpp"
#include "sim/scenario.hpp"
#include "soak_plot.hpp"

namespace {

using namespace rays;
using namespace rays::soak;

nlohmann::json summary_json(const SoakSummary& s) {
    nlohmann::json reacquire = nlohmann::json::array(), causes = nlohmann::json::array();
    for (const Loss& loss : s.losses) {
        reacquire.push_back(loss.reacquire_s);
        causes.push_back(to_string(loss.cause));
    }
    return {{"frames", s.frames},
            {"acquired_s", s.acquired_s},
            {"losses", s.losses.size()},
            {"centred_fraction", s.centred_fraction},
            {"on_target_fraction", s.on_target_fraction},
            {"max_speed_deg_s", s.max_speed_deg_s},
            {"max_speed_px_frame", s.max_speed_px_frame},
            {"reacquire_s", reacquire},
            {"loss_causes", causes},
            {"latency_us_median", s.latency_median_us},
            {"latency_us_p99", s.latency_p99_us},
            {"pan_range_deg", {s.pan_min_deg, s.pan_max_deg}},
            {"tilt_range_deg", {s.tilt_min_deg, s.tilt_max_deg}},
            {"max_rate_deg_s", {s.max_abs_pan_rate_deg_s, s.max_abs_tilt_rate_deg_s}}};
}

nlohmann::json setup_json(const daemon::DaemonConfig& c, long frames, bool lockstep) {
    return {{"scenario", c.sim.scenario}, {"seed", c.sim.seed},        {"fps", c.sim.fps},
            {"latency_frames", c.sim.latency_frames}, {"target_motion", c.control.target_motion},
            {"fov_deg", {c.control.horizontal_fov_deg, c.control.vertical_fov_deg}},
            {"frames", frames},           {"method", c.tracker.method == TrackerMethod::Snake ? "snake" : "rays"},
            {"law", c.control.law},       {"gain", c.control.gain},    {"budget_ms", c.loop.budget_ms}, {"lockstep", lockstep},
            {"rays", c.tracker.tunables.rays.count}, {"hypotheses", c.tracker.tunables.rays.hypotheses},
            {"max_velocity_deg_s", c.ptu.motion.max_velocity_deg_s},
            {"max_accel_deg_s2", c.ptu.motion.max_accel_deg_s2}};
}

void print_summary(const daemon::DaemonConfig& c, const SoakSummary& s, bool lockstep) {
    char budget[48];
    if (lockstep) std::snprintf(budget, sizeof budget, "lockstep (no budget)");
    else std::snprintf(budget, sizeof budget, "budget %g ms", c.loop.budget_ms);
    std::printf("rays-soak: scenario %s seed %d, %ld frames at %g fps; tracker %s, control %s gain %g/s, %s\n",
                c.sim.scenario.c_str(), c.sim.seed, s.frames, c.sim.fps,
                c.tracker.method == TrackerMethod::Snake ? "snake" : "rays", c.control.law.c_str(), c.control.gain,
                budget);
    std::printf("  acquired at %.2f s; losses %zu, centred %.1f %%, contour on target %.1f %%\n", s.acquired_s,
                s.losses.size(), 100 * s.centred_fraction, 100 * s.on_target_fraction);
    std::printf("  fastest target kept: %.1f deg/s (%.2f px/frame)\n", s.max_speed_deg_s, s.max_speed_px_frame);
    for (const Loss& loss : s.losses) {
        if (loss.reacquire_s < 0) std::printf("  lost at %.2f s (%s), not re-acquired\n", loss.start_s, to_string(loss.cause));
        else
            std::printf("  lost at %.2f s (%s), re-acquired after %.2f s\n", loss.start_s, to_string(loss.cause),
                        loss.reacquire_s);
    }
    std::printf("  loop latency (capture to PTU write): median %.0f us, p99 %.0f us\n", s.latency_median_us,
                s.latency_p99_us);
    std::printf("  unit: pan %.1f..%.1f deg, tilt %.1f..%.1f deg, fastest %.1f / %.1f deg/s (limit %g)\n",
                s.pan_min_deg, s.pan_max_deg, s.tilt_min_deg, s.tilt_max_deg, s.max_abs_pan_rate_deg_s,
                s.max_abs_tilt_rate_deg_s, c.ptu.motion.max_velocity_deg_s);
}

// One closed-loop run: its summary printed (or kept for --json), with the plot and trace written when asked.
std::optional<nlohmann::json> run_once(const SoakRun& run, const SoakOptions& options, bool single, SoakSummary& summary) {
    std::string error;
    std::vector<SoakFrame> frames = run_closed_loop(run, error);
    if (frames.empty()) {
        std::fprintf(stderr, "rays-soak: %s\n", error.c_str());
        return std::nullopt;
    }
    summary = summarise(frames);
    if (!options.json) print_summary(run.config, summary, run.lockstep);
    if (single && !options.plot_path.empty() && !write_plot(options.plot_path, frames, error)) {
        std::fprintf(stderr, "rays-soak: plot %s: %s\n", options.plot_path.c_str(), error.c_str());
        return std::nullopt;
    }
    if (single && !options.trace_path.empty() && !write_trace(options.trace_path, frames, error)) {
        std::fprintf(stderr, "rays-soak: trace %s: %s\n", options.trace_path.c_str(), error.c_str());
        return std::nullopt;
    }
    nlohmann::json row = summary_json(summary);
    row["config"] = setup_json(run.config, run.frames, run.lockstep);
    return row;
}

// One run per gain, the rest of `run` as it is; which gain kept the fastest target. `single`: the one
// run whose plot and trace are written.
struct Sweep {
    nlohmann::json rows = nlohmann::json::array();
    double best_gain = 0, best_speed = -1;
};

std::optional<Sweep> sweep_gains(SoakRun run, const std::vector<double>& gains, const SoakOptions& options, bool single) {
    Sweep sweep;
    sweep.best_gain = gains.front();
    for (double gain : gains) {
        run.config.control.gain = gain;
        SoakSummary summary;
        std::optional<nlohmann::json> row = run_once(run, options, single, summary);
        if (!row) return std::nullopt;
        sweep.rows.push_back(*row);
        if (summary.max_speed_deg_s > sweep.best_speed) {
            sweep.best_speed = summary.max_speed_deg_s;
            sweep.best_gain = gain;
        }
    }
    return sweep;
}

// --compare: the proportional law at each gain, the predictive law, the greedy snake; one table.
int compare(const SoakRun& run, const SoakOptions& options) {
    SoakRun proportional_run = run;
    proportional_run.config.control.law = "proportional";
    const std::optional<Sweep> proportional = sweep_gains(proportional_run, options.compare_gains, options, false);
    if (!proportional) return 1;
    const double best_gain = proportional->best_gain, best_speed = proportional->best_speed;
    SoakSummary summary;
    const SoakRun predictive_run = [&] {
        SoakRun r = run;
        r.config.control.law = "predictive";
        return r;
    }();
    std::optional<nlohmann::json> predictive = run_once(predictive_run, options, false, summary);
    if (!predictive) return 1;
    const double predictive_speed = summary.max_speed_deg_s;
    SoakRun snake_run = predictive_run;
    snake_run.config.tracker.method = TrackerMethod::Snake;
    std::optional<nlohmann::json> snake = run_once(snake_run, options, false, summary);
    if (!snake) return 1;
    const double snake_speed = summary.max_speed_deg_s;
    const double law_ratio = predictive_speed / std::max(best_speed, 1e-9);
    const double method_ratio = predictive_speed / std::max(snake_speed, 1e-9);
    if (options.json) {
        std::printf("%s\n", nlohmann::json{{"proportional", proportional->rows},
                                           {"best_proportional_gain", best_gain},
                                           {"predictive", *predictive},
                                           {"snake", *snake},
                                           {"predictive_over_proportional", law_ratio},
                                           {"rays_over_snake", method_ratio}}
                                 .dump()
                                 .c_str());
        return 0;
    }
    std::printf("\nfastest target kept (deg/s), one config, scenario %s:\n", run.config.sim.scenario.c_str());
    std::printf("  active rays, proportional, best gain %g/s: %.1f\n", best_gain, best_speed);
    std::printf("  active rays, predictive (%s model), gain %g/s: %.1f  (%.2f x the proportional)\n",
                run.config.control.target_motion.c_str(), run.config.control.gain, predictive_speed, law_ratio);
    std::printf("  greedy snake (%d points, alpha %g, beta %g, gamma %g, %dx%d, <= %d passes), predictive: %.1f"
                "  (active rays %.2f x faster)\n",
                run.config.tracker.tunables.snake.points, run.config.tracker.tunables.snake.alpha,
                run.config.tracker.tunables.snake.beta, run.config.tracker.tunables.snake.gamma,
                run.config.tracker.tunables.snake.neighbourhood, run.config.tracker.tunables.snake.neighbourhood,
                run.config.tracker.tunables.snake.max_iterations, snake_speed, method_ratio);
    return 0;
}

// --seeds: one run per seed, each summarised, then the totals over them.
int over_seeds(SoakRun run, const SoakOptions& options) {
    nlohmann::json rows = nlohmann::json::array();
    long losses = 0;
    std::map<std::string, long> causes;  // losses by cause, in to_string's words
    for (LossCause cause : kLossCauses) causes[to_string(cause)] = 0;
    double centred = 0, on_target = 0;
    const auto [first, last] = *options.seeds;
    const int count = last - first + 1;
    for (int seed = first; seed <= last; ++seed) {
        run.config.sim.seed = seed;
        SoakSummary summary;
        std::optional<nlohmann::json> row = run_once(run, options, false, summary);
        if (!row) return 1;
        rows.push_back(*row);
        losses += static_cast<long>(summary.losses.size());
        for (const Loss& loss : summary.losses) ++causes[to_string(loss.cause)];
        centred += summary.centred_fraction / count;
        on_target += summary.on_target_fraction / count;
    }
    if (options.json) {
        std::printf("%s\n", nlohmann::json{{"seeds", rows}, {"losses", losses}, {"loss_causes", causes},
                                           {"centred_fraction", centred}, {"on_target_fraction", on_target}}
                                 .dump()
                                 .c_str());
        return 0;
    }
    std::printf("seeds %d-%d, %ld frames each: losses %ld in all, centred %.1f %%, contour on target %.1f %% (means)\n",
                first, last, run.frames, losses, 100 * centred, 100 * on_target);
    std::printf("  losses by what their first frame off target showed:");
    for (LossCause cause : kLossCauses)
        std::printf(" %s %ld%s", to_string(cause), causes[to_string(cause)], cause == kLossCauses.back() ? "\n" : ",");
    return 0;
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
    run.lockstep = options.lockstep;
    run.overlay_dir = options.overlay_dir;
    if (!run.overlay_dir.empty()) {  // made here, as rays-replay does: not a complaint per frame later
        std::error_code ec;
        std::filesystem::create_directories(run.overlay_dir, ec);
        if (ec) {
            std::fprintf(stderr, "rays-soak: --overlay: cannot create %s: %s\n", run.overlay_dir.c_str(), ec.message().c_str());
            return 2;
        }
    }
    run.overlay_from_s = options.overlay_from_s;
    run.overlay_to_s = options.overlay_to_s;
    if (!options.config_path.empty()) {
        if (auto problem = daemon::load_daemon_config(options.config_path, run.config)) {
            std::fprintf(stderr, "rays-soak: %s\n", problem->to_string().c_str());
            return 2;
        }
    }
    if (options.scenario) {
        if (!sim::make_scenario(*options.scenario, 0)) {
            std::fprintf(stderr, "rays-soak: --scenario: '%s' is not a known scenario\n%s\n", options.scenario->c_str(), kUsage);
            return 2;
        }
        run.config.sim.scenario = *options.scenario;
    }
    if (options.seed) run.config.sim.seed = *options.seed;
    if (options.law) run.config.control.law = *options.law;
    if (options.method) run.config.tracker.method = *options.method == "snake" ? TrackerMethod::Snake : TrackerMethod::Rays;
    if (options.gain) run.config.control.gain = *options.gain;
    if (options.budget_ms) run.config.loop.budget_ms = *options.budget_ms;
    if (!options.compare_gains.empty()) return compare(run, options);
    if (options.seeds) return over_seeds(run, options);

    std::vector<double> gains = options.sweep_gains;
    if (gains.empty()) gains.push_back(run.config.control.gain);
    const std::optional<Sweep> sweep = sweep_gains(run, gains, options, gains.size() == 1);
    if (!sweep) return 1;
    if (gains.size() > 1 && !options.json)
        std::printf("best gain for the fastest target kept: %g/s (%.1f deg/s)\n", sweep->best_gain, sweep->best_speed);
    if (options.json) {
        nlohmann::json out = gains.size() == 1 ? sweep->rows.front()
                                               : nlohmann::json{{"sweep", sweep->rows}, {"best_gain", sweep->best_gain}};
        std::printf("%s\n", out.dump().c_str());
    }
    return 0;
}
