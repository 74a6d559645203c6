// SPDX-License-Identifier: Apache-2.0
#include "bench_setup.hpp"

#include <algorithm>
#include <memory>
#include <string_view>

#include "config/tracker_config_io.hpp"
#include "scenes/scene.hpp"

namespace rays::bench {
namespace {

constexpr int kMostRays = 360;  // the densest row of Table 2, Δφ = π/180

}  // namespace

std::optional<std::string> make_setup(const BenchOptions& options, BenchSetup& out) {
    TrackerConfig config;
    if (!options.config_path.empty()) {
        if (const auto error = config::load_ini(options.config_path, config)) return error->to_string();
    }
    if (options.hypotheses) {
        if (const auto error = config::set_param(config, "rays.hypotheses", std::to_string(*options.hypotheses), false))
            return "--hypotheses: " + *error;
    }
    if (config.capacity.max_rays < kMostRays)
        return "rays.max_rays = " + std::to_string(config.capacity.max_rays) + " is below the " +
               std::to_string(kMostRays) + " rays of the densest row";

    const std::unique_ptr<scenes::Scene> scene = scenes::make_scene(options.scene);
    if (!scene) {
        std::string known;
        for (const std::string_view name : scenes::scene_names()) known += (known.empty() ? "" : ", ") + std::string(name);
        return "unknown scene '" + options.scene + "' (known: " + known + ")";
    }
    if (options.frames > scene->frame_count())
        return "--frames " + std::to_string(options.frames) + ": scene '" + options.scene + "' has " +
               std::to_string(scene->frame_count()) + " frames";

    out.config = config;
    out.config_source = options.config_path.empty() ? "built-in defaults" : options.config_path;
    out.scene = options.scene;
    out.images.resize(static_cast<std::size_t>(options.frames));
    out.masks.resize(out.images.size());
    const auto frame = std::make_unique<scenes::SceneFrame>();
    for (int i = 0; i < options.frames; ++i) {
        scene->render(i, *frame);
        out.images[static_cast<std::size_t>(i)] = frame->image;
        out.masks[static_cast<std::size_t>(i)] = frame->mask;
    }
    out.start = scene->init();
    return std::nullopt;
}

TrackerConfig with_ray_count(const TrackerConfig& config, int rays) {
    TrackerConfig c = config;
    c.tunables.rays.count = rays;
    c.tunables.rays.centroid_rays = std::min(c.tunables.rays.centroid_rays, rays);
    return c;
}

}  // namespace rays::bench
