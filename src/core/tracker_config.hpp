// SPDX-License-Identifier: Apache-2.0
// Every setting of the tracking core. Capacities size the buffers once; tunables may change later
// (within the capacities) without allocating. The INI table in config_table.cpp documents each key.
#pragma once
#include <cstdint>

namespace rays {

struct TrackerCapacity {
    int max_rays = 720;        // rays.max_rays: most rays per contour
    int max_hypotheses = 6;    // rays.max_hypotheses: most edge hypotheses per ray (the "no edge" state is extra)
    int max_samples = 160;     // rays.max_samples: most samples along one ray
    int max_snake_points = 128;  // snake.max_points: most points of the greedy snake
};

struct RaysTunables {
    int count = 360;               // rays.count: rays in a full contour (Δφ = 2π / count)
    int hypotheses = 3;            // rays.hypotheses: K, edge hypotheses kept per ray (eq. 13)
    double lambda_min_px = 2.0;    // rays.lambda_min_px: first sample along a ray
    double lambda_max_px = 60.0;   // rays.lambda_max_px: last sample along a ray
    double step_px = 1.0;          // rays.step_px: sample spacing along a ray
    double sigma_px = 1.0;         // rays.sigma_px: Gaussian pre-smoothing
    double alpha = 0.02;           // rays.alpha: first-order smoothness (eq. 9)
    double beta = 1e-6;           // rays.beta: second-order smoothness (eq. 9)
    double jump_cost = 0.002;      // rays.jump_cost: most one smoothness term between edges charges while tracking (0: never truncated)
    double edge_floor = 2.0;       // rays.edge_floor: |dρ/dλ| below this (grey/px) is noise
    double none_cost = 0.15;       // rays.none_cost: cost of the "no edge on this ray" state
    double polarity_weight = 0.6;  // rays.polarity_weight: extra cost of an edge of the wrong sign
    double region_weight = 0.8;    // rays.region_weight: 1-D region term along each ray
    double temporal_weight = 0.1;  // rays.temporal_weight: pull toward the previous frame's contour
    double foreground_weight = 2.0;  // rays.foreground_weight: edges out of the still camera's foreground (0: off)
    double appearance_weight = 1.0;  // rays.appearance_weight: rims where the target's colours end (0: off)
    bool motion_layers = true;     // rays.motion_layers: while the view moves, where things move with the target or the view
    double hypothesis_separation_px = 2.0;  // rays.hypothesis_separation_px: minimum gap between hypotheses (eq. 15)
    int centroid_rays = 32;        // rays.centroid_rays: rays used while m converges (eq. 11)
    int centroid_iterations = 6;   // rays.centroid_iterations: cap on re-extractions
    double centroid_tol_px = 0.3;  // rays.centroid_tol_px: stop when m moves less than this
};

struct DetectTunables {
    double threshold = 20.0;       // detect.threshold: initial |difference| threshold (grey levels)
    double threshold_min = 6.0;    // detect.threshold_min
    double threshold_max = 120.0;  // detect.threshold_max
    int min_area_px = 12;          // detect.min_area_px: smallest region taken as a target
    int max_regions = 12;          // detect.max_regions: more regions than this means noise
    double max_area_fraction = 0.35;  // detect.max_area_fraction: a larger region means noise or ego-motion
};

struct AttentionTunables {
    double max_area_change = 0.6;     // attention.max_area_change: relative area change per frame
    double max_jump_px = 20.0;        // attention.max_jump_px: centroid distance from the prediction
    double max_none_fraction = 0.6;   // attention.max_none_fraction: rays with no edge
    double min_area_px = 20.0;        // attention.min_area_px
    double max_area_fraction = 0.6;   // attention.max_area_fraction: of the frame
    int lost_frames = 0;              // attention.lost_frames: frames spent in "lost" before detecting again (0: none)
};

// The greedy active contour of Williams & Shah (1992), the baseline the product compares active rays
// with. Each pass moves every point to the best position in a neighbourhood × neighbourhood window
// round it, so one pass follows motion of at most neighbourhood / 2 px: a larger window follows
// faster targets at (neighbourhood)² evaluations per point and pass (W&S use 3 × 3).
struct SnakeTunables {
    int points = 40;                     // snake.points: points on the contour
    double alpha = 1.0;                  // snake.alpha: weight of the continuity term (even spacing)
    double beta = 1.0;                   // snake.beta: weight of the curvature term (0 at corners)
    double gamma = 1.2;                  // snake.gamma: weight of the image term (-|grad I|)
    int neighbourhood = 5;               // snake.neighbourhood: odd side of the search window, px
    int max_iterations = 40;             // snake.max_iterations: most greedy passes per frame
    double moved_fraction = 0.05;        // snake.moved_fraction: converged when fewer points moved in a pass
    double corner_curvature = 0.25;      // snake.corner_curvature: W&S corner rule, curvature above this...
    double corner_edge = 20.0;           // snake.corner_edge: ...on an edge stronger than this (grey/px)
    double image_floor = 5.0;            // snake.image_floor: least max - min of |grad I| when normalising (grey/px)
    double edge_floor = 4.0;             // snake.edge_floor: a point on a weaker |grad I| has no edge (grey/px)
    double initial_radius_factor = 1.3;  // snake.initial_radius_factor: start circle / detected radius
    double sigma_px = 1.0;               // snake.sigma_px: Gaussian pre-smoothing
};

struct TrackerTunables {
    RaysTunables rays;
    DetectTunables detect;
    AttentionTunables attention;
    SnakeTunables snake;
    bool predict = true;  // track.predict: constant-velocity prediction of m into the next frame
};

// Which contour tracker runs: active rays or the greedy-snake baseline (track.method).
enum class TrackerMethod { Rays, Snake };

struct TrackerConfig {
    TrackerCapacity capacity;
    TrackerTunables tunables;
    TrackerMethod method = TrackerMethod::Rays;  // track.method: fixed at start
};

}  // namespace rays
