// SPDX-License-Identifier: Apache-2.0
// What the snake tests share: frames with one drawn target, a clock that advances on every read,
// and the IoU of a contour with the target's mask.
#pragma once
#include <chrono>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/clock.hpp"
#include "core/contour.hpp"
#include "scenes/render.hpp"
#include "scenes/scene.hpp"

namespace rays::snake_test {

// A bright target (grey 200) on a dark plain background (50) under σ 3 noise, as the "disc" scene.
template <class Shape>
void draw(const Shape& target, scenes::SceneFrame& out, std::uint64_t seed = 1) {
    const auto canvas = std::make_unique<scenes::Canvas>();
    scenes::Random random(seed);
    canvas->fill(50);
    canvas->paint(target, 200, true);
    canvas->noise(3, random);
    canvas->finish(out);
}

inline double iou(const Contour& contour, const scenes::SceneFrame& frame) {
    std::vector<Point> polygon(static_cast<std::size_t>(contour.size));
    for (int i = 0; i < contour.size; ++i) polygon[static_cast<std::size_t>(i)] = contour.points[static_cast<std::size_t>(i)].p;
    return scenes::polygon_mask_iou(polygon, frame.mask);
}

// Advances by a fixed step each time it is read, so the reads themselves spend the time budget.
class SteppingClock final : public Clock {
public:
    explicit SteppingClock(std::chrono::nanoseconds step) : step_(step) {}
    TimePoint now() const override {
        ++reads_;
        return t_ += step_;
    }
    TimePoint last_read() const { return t_; }
    int reads() const { return reads_; }

private:
    std::chrono::nanoseconds step_;
    mutable TimePoint t_{};
    mutable int reads_ = 0;
};

}  // namespace rays::snake_test
