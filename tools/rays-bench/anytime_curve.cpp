// SPDX-License-Identifier: Apache-2.0
#include "anytime_curve.hpp"

#include <chrono>

#include "core/tracker.hpp"
#include "scenes/scene.hpp"

namespace rays::bench {
namespace {

constexpr int kBudgetsUs[] = {10, 20, 40, 60, 80, 100, 150, 200, 300, 500, 1000};

AnytimePoint measure_point(const BenchSetup& setup, int budget_us) {
    const SteadyClock clock;
    Tracker tracker(setup.config, clock);
    tracker.start_at(setup.start);
    std::vector<Point> polygon(static_cast<std::size_t>(tracker.capacity().max_rays));
    double iou_sum = 0;
    long ray_sum = 0;
    AnytimePoint point;
    point.budget_us = budget_us;
    for (std::size_t i = 0; i < setup.images.size(); ++i) {
        const TimePoint deadline = clock.now() + std::chrono::microseconds(budget_us);
        if (tracker.process(setup.images[i], deadline).state != TrackState::Tracking) continue;
        const Contour& contour = tracker.contour();
        for (int k = 0; k < contour.size; ++k) polygon[static_cast<std::size_t>(k)] = contour.points[static_cast<std::size_t>(k)].p;
        iou_sum += scenes::polygon_mask_iou({polygon.data(), static_cast<std::size_t>(contour.size)}, setup.masks[i]);
        ray_sum += contour.size;
        ++point.tracking;
    }
    point.iou = iou_sum / static_cast<double>(setup.images.size());
    point.rays = point.tracking == 0 ? 0 : static_cast<double>(ray_sum) / point.tracking;
    return point;
}

}  // namespace

std::vector<AnytimePoint> measure_anytime_curve(const BenchSetup& setup) {
    std::vector<AnytimePoint> curve;
    for (const int budget : kBudgetsUs) curve.push_back(measure_point(setup, budget));
    return curve;
}

}  // namespace rays::bench
