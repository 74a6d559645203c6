// SPDX-License-Identifier: Apache-2.0
// Every key of the tracking core's configuration: section [rays] holds the capacities and the
// Active Rays settings, then [detect] (motion detection), [attention] (plausibility checks that
// declare the target lost), [track] (which tracker, and prediction) and [snake] (the greedy-snake
// baseline of Williams & Shah, 1992). Defaults are the member initialisers in
// src/core/tracker_config.hpp; equation numbers refer to Denzler & Niemann, Active Rays.
#include "config/config_table.hpp"

#include <cmath>

#include "config/param_text.hpp"

namespace rays::config {
namespace {

void add_capacities(ParamTable<TrackerConfig>& table) {
    table.section("rays", ParamKind::Capacity, &TrackerConfig::capacity)
        .add("max_rays", &TrackerCapacity::max_rays, "rays", 4, 4096, "most rays per contour; sizes the ray buffers")
        .add("max_hypotheses", &TrackerCapacity::max_hypotheses, "", 1, 32,
             "most edge hypotheses per ray (the no-edge state is extra)")
        .add("max_samples", &TrackerCapacity::max_samples, "samples", 2, 1024, "most samples along one ray");
}

void add_rays(ParamTable<TrackerConfig>& table) {
    table.section("rays", ParamKind::Tunable, [](TrackerConfig& config) -> auto& { return config.tunables.rays; })
        .add("count", &RaysTunables::count, "rays", 4, 4096, "rays in a full contour (angle step 2 pi / count)")
        .add("hypotheses", &RaysTunables::hypotheses, "", 1, 32, "K, edge hypotheses kept per ray (eq. 13)")
        .add("lambda_min_px", &RaysTunables::lambda_min_px, "px", 0, 256, "distance of the first sample along a ray")
        .add("lambda_max_px", &RaysTunables::lambda_max_px, "px", 1, 256, "distance of the last sample along a ray")
        .add("step_px", &RaysTunables::step_px, "px", 0.05, 16, "sample spacing along a ray")
        .add("sigma_px", &RaysTunables::sigma_px, "px", 0, 2.5,
             "sigma of the Gaussian pre-smoothing (0: none; the smoother reaches 8/3 px at most)")
        .add("alpha", &RaysTunables::alpha, "", 0, 10, "first-order smoothness weight of the contour (eq. 9)")
        .add("beta", &RaysTunables::beta, "", 0, 10, "second-order smoothness weight of the contour (eq. 9)")
        .add("jump_cost", &RaysTunables::jump_cost, "", 0, 10,
             "while tracking, the most one smoothness term between two edges charges, so a thin limb can step out "
             "(0: never truncated)")
        .add("edge_floor", &RaysTunables::edge_floor, "grey/px", 0, 255,
             "an edge strength |d rho / d lambda| below this is noise")
        .add("none_cost", &RaysTunables::none_cost, "", 0, 10, "cost of the 'no edge on this ray' state")
        .add("polarity_weight", &RaysTunables::polarity_weight, "", 0, 10, "extra cost of an edge of the wrong sign")
        .add("region_weight", &RaysTunables::region_weight, "", 0, 10, "weight of the 1-D region term along each ray")
        .add("foreground_weight", &RaysTunables::foreground_weight, "", 0, 10, "weight of the still camera's foreground: edges where a ray leaves it cost less (0: no background is kept)")
        .add("appearance_weight", &RaysTunables::appearance_weight, "", 0, 10, "weight of the target's colours (colour sources): a rim away from where a ray's colours turn from target to background costs more (0: no colour model is kept)")
        .add("motion_layers", &RaysTunables::motion_layers,
             "while the view moves, where things move with the target or with the view: with colours, both, beside "
             "them; on grey, while the unit turns, the scene only (false: neither)")
        .add("temporal_weight", &RaysTunables::temporal_weight, "", 0, 10,
             "pull toward the previous frame's contour")
        .add("hypothesis_separation_px", &RaysTunables::hypothesis_separation_px, "px", 0, 64,
             "minimum gap between the hypotheses of one ray (eq. 15)")
        .add("centroid_rays", &RaysTunables::centroid_rays, "rays", 4, 4096,
             "rays used while the centre m converges (eq. 11)")
        .add("centroid_iterations", &RaysTunables::centroid_iterations, "", 1, 100,
             "most contour extractions while the centre m converges")
        .add("centroid_tol_px", &RaysTunables::centroid_tol_px, "px", 0, 64,
             "the centre m has converged when it moves less than this");
}

void add_detect(ParamTable<TrackerConfig>& table) {
    table.section("detect", ParamKind::Tunable, [](TrackerConfig& config) -> auto& { return config.tunables.detect; })
        .add("threshold", &DetectTunables::threshold, "grey", 1, 255, "initial threshold on the frame difference")
        .add("threshold_min", &DetectTunables::threshold_min, "grey", 1, 255, "lowest the threshold may adapt to")
        .add("threshold_max", &DetectTunables::threshold_max, "grey", 1, 255, "highest the threshold may adapt to")
        .add("min_area_px", &DetectTunables::min_area_px, "px^2", 1, 16384, "smallest region taken as a target")
        .add("max_regions", &DetectTunables::max_regions, "", 1, 1024, "more moving regions than this means noise")
        .add("max_area_fraction", &DetectTunables::max_area_fraction, "", 0, 1,
             "a region larger than this fraction of the frame means noise or ego-motion");
}

void add_attention(ParamTable<TrackerConfig>& table) {
    table
        .section("attention", ParamKind::Tunable,
                 [](TrackerConfig& config) -> auto& { return config.tunables.attention; })
        .add("max_area_change", &AttentionTunables::max_area_change, "", 0, 10,
             "largest relative change of the contour's area from one frame to the next")
        .add("max_jump_px", &AttentionTunables::max_jump_px, "px", 0, 256,
             "largest distance of the contour's centroid from its prediction")
        .add("max_none_fraction", &AttentionTunables::max_none_fraction, "", 0, 1,
             "largest fraction of rays that found no edge")
        .add("min_area_px", &AttentionTunables::min_area_px, "px^2", 0, 16384, "smallest area of a tracked contour")
        .add("max_area_fraction", &AttentionTunables::max_area_fraction, "", 0, 1,
             "largest area of a tracked contour, as a fraction of the frame")
        .add("lost_frames", &AttentionTunables::lost_frames, "frames", 0, 1000,
             "frames spent in 'lost' before detecting again (0: active rays look for a target the contour "
             "check lost again by its looks in the same frame)");
}

void add_track(ParamTable<TrackerConfig>& table) {
    table.section("track", ParamKind::Capacity, [](TrackerConfig& config) -> auto& { return config; })
        .add_choice("method", &TrackerConfig::method, "rays|snake",
                    "the contour tracker: active rays, or the greedy snake of Williams & Shah (the baseline)");
    table.section("track", ParamKind::Tunable, &TrackerConfig::tunables)
        .add("predict", &TrackerTunables::predict, "predict the centre m into the next frame at constant velocity");
}

void add_snake(ParamTable<TrackerConfig>& table) {
    table.section("snake", ParamKind::Capacity, &TrackerConfig::capacity)
        .add("max_points", &TrackerCapacity::max_snake_points, "points", 8, 1024,
             "most points of the greedy snake; sizes its buffers");
    table.section("snake", ParamKind::Tunable, [](TrackerConfig& config) -> auto& { return config.tunables.snake; })
        .add("points", &SnakeTunables::points, "points", 8, 1024, "points on the snake")
        .add("alpha", &SnakeTunables::alpha, "", 0, 10, "weight of the continuity term (even spacing of the points)")
        .add("beta", &SnakeTunables::beta, "", 0, 10, "weight of the curvature term (dropped at corners)")
        .add("gamma", &SnakeTunables::gamma, "", 0, 10, "weight of the image term (-|grad I|)")
        .add("neighbourhood", &SnakeTunables::neighbourhood, "px", 3, 15,
             "odd side of the square window a point moves within per pass; larger follows faster motion at "
             "more cost (Williams & Shah: 3)")
        .add("max_iterations", &SnakeTunables::max_iterations, "", 1, 1000, "most greedy passes per frame")
        .add("moved_fraction", &SnakeTunables::moved_fraction, "", 0, 1,
             "the snake has converged when fewer than this fraction of its points moved in a pass")
        .add("corner_curvature", &SnakeTunables::corner_curvature, "", 0, 4,
             "a point is a corner (no curvature term) where the curvature peaks above this...")
        .add("corner_edge", &SnakeTunables::corner_edge, "grey/px", 0, 1000, "...on an edge at least this strong")
        .add("image_floor", &SnakeTunables::image_floor, "grey/px", 0.01, 1000,
             "least spread (max - min) of |grad I| in a window when normalising the image term")
        .add("edge_floor", &SnakeTunables::edge_floor, "grey/px", 0, 1000,
             "a point on a weaker |grad I| has no edge (see attention.max_none_fraction)")
        .add("initial_radius_factor", &SnakeTunables::initial_radius_factor, "", 0.5, 4,
             "radius of the start circle, relative to the detected target's radius")
        .add("sigma_px", &SnakeTunables::sigma_px, "px", 0, 2.5,
             "sigma of the Gaussian pre-smoothing (0: none; the smoother reaches 8/3 px at most)");
}

CrossRule neighbourhood_is_odd() {
    CrossRule rule;
    rule.keys = {"snake.neighbourhood"};
    rule.check = [](const ParamLookup& value) -> std::optional<std::string> {
        const double side = value("snake.neighbourhood");
        if (std::fmod(side, 2.0) == 1.0) return std::nullopt;
        return "snake.neighbourhood = " + format_number(side) + " must be odd (a window centred on the point)";
    };
    return rule;
}

CrossRule samples_fit_capacity() {
    CrossRule rule;
    rule.keys = {"rays.lambda_min_px", "rays.lambda_max_px", "rays.step_px", "rays.max_samples"};
    rule.check = [](const ParamLookup& value) -> std::optional<std::string> {
        int samples = samples_per_ray(value("rays.lambda_min_px"), value("rays.lambda_max_px"), value("rays.step_px"));
        double capacity = value("rays.max_samples");
        if (samples <= capacity) return std::nullopt;
        return "rays.lambda_min_px to rays.lambda_max_px in steps of rays.step_px gives " + std::to_string(samples) +
               " samples per ray, more than rays.max_samples = " + format_number(capacity);
    };
    return rule;
}

ParamTable<TrackerConfig> build_tracker_params() {
    ParamTable<TrackerConfig> table;
    add_capacities(table);
    add_rays(table);
    add_detect(table);
    add_attention(table);
    add_track(table);
    add_snake(table);
    table.add_rule(at_most("rays.count", "rays.max_rays"));
    table.add_rule(at_most("rays.hypotheses", "rays.max_hypotheses"));
    table.add_rule(less_than("rays.lambda_min_px", "rays.lambda_max_px"));
    table.add_rule(samples_fit_capacity());
    table.add_rule(at_most("rays.centroid_rays", "rays.count"));
    table.add_rule(at_most("detect.threshold_min", "detect.threshold"));
    table.add_rule(at_most("detect.threshold", "detect.threshold_max"));
    table.add_rule(at_most("snake.points", "snake.max_points"));
    table.add_rule(neighbourhood_is_odd());
    return table;
}

}  // namespace

const ParamTable<TrackerConfig>& tracker_params() {
    static const ParamTable<TrackerConfig> table = build_tracker_params();
    return table;
}

int samples_per_ray(double lambda_min_px, double lambda_max_px, double step_px) {
    return static_cast<int>(std::floor((lambda_max_px - lambda_min_px) / step_px)) + 1;
}

}  // namespace rays::config
