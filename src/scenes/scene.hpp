// SPDX-License-Identifier: Apache-2.0
// Reproducible synthetic scenes: 128×128 grey frames with the target's visible mask and truth,
// drawn from fixed parameters and seeds kept here, so every figure can be reproduced.
#pragma once
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "core/image.hpp"

namespace rays::scenes {

struct Truth {
    double cx = 0, cy = 0;  // centroid of the visible mask, pixel centres at integers; 0 when hidden
    double area = 0;        // visible pixels (the mask's count); 0 when the target is hidden
};

struct SceneFrame {
    GreyImage image;
    GreyImage mask;  // 255 where the target is visible
    Truth truth;
};

class Scene {
public:
    virtual ~Scene() = default;
    virtual std::string_view name() const = 0;
    virtual std::string_view description() const = 0;
    virtual int frame_count() const = 0;
    // Deterministic and random access: the same index always gives the same frame.
    virtual void render(int index, SceneFrame& out) const = 0;
    // The target's centre in frame 0: the truth's centroid there.
    virtual Point init() const;
};

std::unique_ptr<Scene> make_scene(std::string_view name);  // nullptr for an unknown name
std::vector<std::string_view> scene_names();

// IoU of a polygon (even-odd fill sampled at pixel centres, as ../shared/tools/score-contours.py
// does) with mask > 127. Fewer than 3 points give 0.
double polygon_mask_iou(std::span<const Point> polygon, const GreyImage& mask);
// Centroid of that same raster of the polygon (what the scorer compares with the truth); NaN when
// the raster is empty.
Point polygon_centroid_px(std::span<const Point> polygon);

}  // namespace rays::scenes
