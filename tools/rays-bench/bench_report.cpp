// SPDX-License-Identifier: Apache-2.0
#include "bench_report.hpp"

#include "common/frame_kernel.hpp"
#include "config/tracker_config_io.hpp"

namespace rays::bench {
namespace {

constexpr const char* kTimingNote =
    "timings: steady_clock on this machine, no CPU pinning; the paper's figures are for an HP 735/99";

}  // namespace

void print_report(std::FILE* out, const BenchSetup& setup, const std::vector<TimingRow>& rows,
                  const std::vector<AnytimePoint>& curve) {
    const RaysTunables& r = setup.config.tunables.rays;
    std::fprintf(out, "scene %s, %zu frames, start point given in frame 0\n", setup.scene.c_str(), setup.images.size());
    std::fprintf(out, "λ %g..%g px, step %g px, K = %d, α = %g, β = %g, σ = %g px (%s)\n", r.lambda_min_px,
                 r.lambda_max_px, r.step_px, r.hypotheses, r.alpha, r.beta, r.sigma_px, setup.config_source.c_str());
    std::fprintf(out, "%s; frame kernels: %s\n\n", kTimingNote, frame_kernel_build());

    std::fprintf(out, "Table 2: time per frame, tracking frames only (first %d skipped), far deadline\n",
                 kWarmupFrames);
    std::fprintf(out, "  Δφ      rays  frames  median µs   p99 µs   max µs   frames/s   HP 735 (paper)\n");
    for (const TimingRow& row : rows) {
        if (row.frames == 0) {
            std::fprintf(out, "  π/%-4d  %4d  %6d  (the target was never tracked)   %10.0f ms\n", row.rays / 2, row.rays,
                         row.frames, row.paper_ms);
            continue;
        }
        std::fprintf(out, "  π/%-4d  %4d  %6d  %9.1f  %7.1f  %7.1f  %9.0f   %10.0f ms\n", row.rays / 2, row.rays,
                     row.frames, row.median_us, row.p99_us, row.max_us, row.fps, row.paper_ms);
    }

    std::fprintf(out, "\nAny-time curve: deadline = frame start + budget, rays.count = %d\n", r.count);
    std::fprintf(out, "  budget µs  contour IoU  mean rays  tracking frames\n");
    for (const AnytimePoint& p : curve)
        std::fprintf(out, "  %9d  %11.3f  %9.1f  %15d\n", p.budget_us, p.iou, p.rays, p.tracking);
    std::fprintf(out, "(IoU: mean over all frames, 0 where not tracking; rays: mean over tracking frames)\n");
}

nlohmann::ordered_json report_json(const BenchSetup& setup, const std::vector<TimingRow>& rows,
                           const std::vector<AnytimePoint>& curve) {
    const RaysTunables& r = setup.config.tunables.rays;
    nlohmann::ordered_json config = {
        {"config_file", setup.config_source},
        {"scene", setup.scene},
        {"frames", setup.images.size()},
        {"lambda_min_px", r.lambda_min_px},
        {"lambda_max_px", r.lambda_max_px},
        {"step_px", r.step_px},
        {"hypotheses", r.hypotheses},
        {"alpha", r.alpha},
        {"beta", r.beta},
        {"sigma_px", r.sigma_px},
        {"anytime_rays", r.count},
        {"warmup_frames", kWarmupFrames},
        {"note", kTimingNote},
        {"frame_kernels", frame_kernel_build()},
        {"settings", config::to_json(setup.config)},
    };
    nlohmann::ordered_json json_rows = nlohmann::ordered_json::array();
    for (const TimingRow& row : rows) {
        auto time_or_null = [&](double v) { return row.frames == 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v); };
        json_rows.push_back({{"dphi", row.dphi},
                             {"rays", row.rays},
                             {"median_us", time_or_null(row.median_us)},
                             {"p99_us", time_or_null(row.p99_us)},
                             {"max_us", time_or_null(row.max_us)},
                             {"fps", time_or_null(row.fps)},
                             {"frames", row.frames},
                             {"paper_ms", row.paper_ms}});
    }
    nlohmann::ordered_json anytime = nlohmann::ordered_json::array();
    for (const AnytimePoint& p : curve)
        anytime.push_back({{"budget_us", p.budget_us}, {"iou", p.iou}, {"rays", p.rays}, {"tracking", p.tracking}});
    return {{"config", config}, {"rows", json_rows}, {"anytime", anytime}};
}

}  // namespace rays::bench
