// SPDX-License-Identifier: Apache-2.0
#include "soak_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace rays::soak {
namespace {

constexpr double kCentre = (kFrameSize - 1) / 2.0;

double distance(Point a, Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

double percentile(std::vector<double> values, double q) {
    if (values.empty()) return 0;
    const auto n = static_cast<double>(values.size());
    auto k = static_cast<std::size_t>(std::min(n - 1, std::floor(q * n)));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
}

}  // namespace

const char* to_string(LossCause cause) {
    switch (cause) {
        case LossCause::LeftImage: return "target left the image";
        case LossCause::NoContour: return "no contour";
        case LossCause::OffTarget: return "contour off the target";
    }
    return "?";
}

bool on_target(const SoakFrame& f) {
    return f.target_in_image && f.has_contour && distance(f.contour_px, f.truth_px) <= kOnTargetPx;
}

SoakSummary summarise(const std::vector<SoakFrame>& frames) {
    SoakSummary s;
    s.frames = static_cast<long>(frames.size());
    if (frames.empty()) return s;
    long centred = 0, tracked = 0;
    int off_run = 0;
    bool lost = false;
    bool seen_loss = false;
    std::vector<double> latencies;
    latencies.reserve(frames.size());
    s.pan_min_deg = s.pan_max_deg = frames.front().pan_deg;
    s.tilt_min_deg = s.tilt_max_deg = frames.front().tilt_deg;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const SoakFrame& f = frames[k];
        const bool on = on_target(f);
        if (f.target_in_image && distance(f.truth_px, {kCentre, kCentre}) <= kOnTargetPx) ++centred;
        if (on) ++tracked;
        if (on && s.acquired_s < 0) s.acquired_s = f.t_s;
        off_run = on ? 0 : off_run + 1;
        if (s.acquired_s < 0) {
            off_run = 0;  // still acquiring
        } else if (!lost && (!f.target_in_image || off_run > kOffFramesForLoss)) {
            lost = seen_loss = true;
            const SoakFrame& first = frames[k + 1 - static_cast<std::size_t>(std::max(off_run, 1))];
            const LossCause cause = !first.target_in_image ? LossCause::LeftImage
                                    : !first.has_contour   ? LossCause::NoContour
                                                           : LossCause::OffTarget;
            s.losses.push_back({first.t_s, -1, cause});
        } else if (lost && on) {
            lost = false;
            s.losses.back().reacquire_s = f.t_s - s.losses.back().start_s;
        }
        if (on && !seen_loss) {
            s.max_speed_deg_s = std::max(s.max_speed_deg_s, f.speed_deg_s);
            s.max_speed_px_frame = std::max(s.max_speed_px_frame, f.speed_px_frame);
        }
        latencies.push_back(f.latency_us);
        s.max_abs_pan_rate_deg_s = std::max(s.max_abs_pan_rate_deg_s, std::abs(f.pan_rate_deg_s));
        s.max_abs_tilt_rate_deg_s = std::max(s.max_abs_tilt_rate_deg_s, std::abs(f.tilt_rate_deg_s));
        s.pan_min_deg = std::min(s.pan_min_deg, f.pan_deg);
        s.pan_max_deg = std::max(s.pan_max_deg, f.pan_deg);
        s.tilt_min_deg = std::min(s.tilt_min_deg, f.tilt_deg);
        s.tilt_max_deg = std::max(s.tilt_max_deg, f.tilt_deg);
    }
    s.centred_fraction = static_cast<double>(centred) / static_cast<double>(frames.size());
    s.on_target_fraction = static_cast<double>(tracked) / static_cast<double>(frames.size());
    s.latency_median_us = percentile(latencies, 0.5);
    s.latency_p99_us = percentile(latencies, 0.99);
    return s;
}

}  // namespace rays::soak
