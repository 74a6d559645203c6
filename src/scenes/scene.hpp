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
    double cx = 0, cy = 0;  // centroid of the visible mask, pixel centres at integers
    double area = 0;        // visible pixels
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
    // The target's centre in frame 0.
    Point init() const;
};

std::unique_ptr<Scene> make_scene(std::string_view name);  // nullptr for an unknown name
std::vector<std::string_view> scene_names();

// IoU of a polygon (even-odd fill sampled at pixel centres, as ../shared/tools/score-contours.py
// does) with mask > 127. Fewer than 3 points give 0.
double polygon_mask_iou(std::span<const Point> polygon, const GreyImage& mask);

}  // namespace rays::scenes
