// SPDX-License-Identifier: Apache-2.0
// A grey scene drawn by the tests while the view moves: a dark textured target on a bright textured
// world that the camera pans across, with dark poles or a dark block standing in the world if asked,
// and the tracker that follows it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/tracker.hpp"
#include "scenes/scene.hpp"
#include "support/block_texture.hpp"

namespace rays::test {

struct PanningScene {
    static constexpr double kA = 12.0, kB = 9.0;  // the target's half axes, px
    SteadyClock clock;
    Tracker tracker;
    std::unique_ptr<scenes::SceneFrame> frame = std::make_unique<scenes::SceneFrame>();
    double size = 1.0;  // the target's size, as a share of kA, kB
    bool poles = false;  // dark poles 2 kPoleHalfWidth px wide stand in the world every kPoleEvery px: edges that show any drift
    bool block = false;  // a dark block stands in the world at kBlock (x0, y0, x1, y1), as grey as the target
    std::optional<Point> twin;  // a look-alike centred here in the view: the target's size and texture, not its mask
    // The caller tells the tracker the unit turns (allow_detection(false)) and how far that moved the
    // view since the previous frame (expect_view_shift), as the daemon does.
    bool turning = false;
    double told_share = 1.0;        // of the view's shift, what the caller tells (a miscalibrated unit: not 1)
    std::optional<Point> last_pan;  // the previous frame's

    static constexpr double kBlock[4] = {80.0, 50.0, 92.0, 78.0};
    static constexpr int kPoleEvery = 24, kPoleHalfWidth = 3;

    explicit PanningScene(const TrackerConfig& config = TrackerConfig{}) : tracker(config, clock) {}

    // Draws the view from `pan` (the view at x shows the world at x + pan) with the target centred
    // at `target` in the view (none when `hidden`), and tracks it.
    TrackState step(Point pan, Point target, bool hidden = false) {
        const Point twin_at = twin.value_or(Point{-1e3, -1e3});  // none: far off the view
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const double u = (x - target.x) / (size * kA), v = (y - target.y) / (size * kB);
                const bool on = !hidden && u * u + v * v <= 1.0;
                const double tu = (x - twin_at.x) / (size * kA), tv = (y - twin_at.y) / (size * kB);
                const bool on_twin = !on && tu * tu + tv * tv <= 1.0;
                const double world_x = x + pan.x, world_y = y + pan.y;
                const double pole = world_x - kPoleEvery * std::floor(world_x / kPoleEvery);  // 0 … kPoleEvery
                const double dark = poles ? std::clamp(kPoleHalfWidth + 0.5 - std::abs(pole - kPoleHalfWidth), 0.0, 1.0) : 0.0;
                const bool in_block = block && world_x >= kBlock[0] && world_x <= kBlock[2] && world_y >= kBlock[1] && world_y <= kBlock[3];
                const double grey = on         ? smooth_blocks(x - target.x, y - target.y, 7u, 4.0, 20, 50)
                                    : on_twin  ? smooth_blocks(x - twin_at.x, y - twin_at.y, 7u, 4.0, 20, 50)
                                    : in_block ? smooth_blocks(world_x, world_y, 3u, 4.0, 20, 50)
                                               : (1.0 - dark) * smooth_blocks(world_x, world_y, 1u, 6.0, 100, 130) + dark * 25.0;
                frame->image.at(x, y) = static_cast<std::uint8_t>(std::lround(grey));
                frame->mask.at(x, y) = on ? 255 : 0;
            }
        tracker.allow_detection(!turning);
        // The view at x shows the world at x + pan: the world moves by the pan's change the other way.
        tracker.expect_view_shift(turning && last_pan ? std::optional<Point>({told_share * (last_pan->x - pan.x), told_share * (last_pan->y - pan.y)})
                                                      : std::nullopt);
        last_pan = pan;
        return tracker.process(frame->image, TimePoint::max()).state;
    }

    // The target's box (at size 1) centred at `centre` in the view, as a person draws it to start.
    static Box box_at(Point centre) { return {centre.x - kA, centre.y - kB, 2 * kA + 1, 2 * kB + 1}; }

    // The contour's intersection over union with the target's mask.
    double contour_iou() const {
        std::vector<Point> polygon;
        for (int k = 0; k < tracker.contour().size; ++k) polygon.push_back(tracker.contour().points[static_cast<std::size_t>(k)].p);
        return scenes::polygon_mask_iou(polygon, frame->mask);
    }

    bool on_target() const {
        const Point c = tracker.contour().centroid;
        const int px = static_cast<int>(std::lround(c.x)), py = static_cast<int>(std::lround(c.y));
        return px >= 0 && py >= 0 && px < kFrameSize && py < kFrameSize && frame->mask.at(px, py) == 255;
    }
};

}  // namespace rays::test
