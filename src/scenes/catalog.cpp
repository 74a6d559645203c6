// SPDX-License-Identifier: Apache-2.0
// The catalogue of scenes: name, description, length and seed of each script in scripts.cpp.
#include <array>
#include <cstdint>

#include "scenes/scripts.hpp"

namespace rays::scenes {
namespace {

struct Entry {
    std::string_view name, description;
    int frames;
    std::uint64_t seed;  // of the per-frame noise
    scripts::Script script;
};

constexpr std::array kCatalog{
    Entry{"disc", "a bright disc circling slowly on a dark plain background", 300, 1, scripts::disc},
    Entry{"vanish", "a disc that moves for 60 frames, is gone for 40 and comes back elsewhere", 300, 2, scripts::vanish},
    Entry{"clutter", "a bright ellipse over random rectangles and lines with strong edges (easy)", 300, 3, scripts::clutter},
    Entry{"star", "a rotating concave five-pointed star drifting over a textured background (easy)", 300, 4, scripts::star},
    Entry{"walker-pole", "a dark walking silhouette passing in front of a dark pole (hard)", 300, 5, scripts::walker_pole},
    Entry{"weak-contrast", "a target 18 grey levels off its surround, near stronger background edges (hard)", 300, 6,
          scripts::weak_contrast},
    Entry{"shadow", "a bright blob crossing a strong diagonal sunlight/shadow border (hard)", 300, 7, scripts::shadow},
    Entry{"occluder", "an ellipse passing behind a dark vertical bar; the mask is the visible part (hard)", 300, 8,
          scripts::occluder},
    Entry{"speed-ramp", "an ellipse running back and forth, speed ramping from 2 to 16 px/frame (hard)", 400, 9,
          scripts::speed_ramp},
    Entry{"noise-blur", "a medium-contrast ellipse under blur and heavy noise (easy)", 300, 10, scripts::noise_blur},
    Entry{"approach", "a walker approaching the camera, growing from 25 to 75 px tall (hard)", 300, 11, scripts::approach},
    Entry{"camouflage", "an ellipse 12 grey levels below a busy texture's mean, its rim weaker than the texture's edges (hard)",
          300, 12, scripts::camouflage},
};

class ScriptedScene final : public Scene {
public:
    explicit ScriptedScene(const Entry& entry) : entry_(entry) {}
    std::string_view name() const override { return entry_.name; }
    std::string_view description() const override { return entry_.description; }
    int frame_count() const override { return entry_.frames; }
    void render(int index, SceneFrame& out) const override {
        Canvas canvas;
        Random random(entry_.seed * 1000003ull + static_cast<std::uint64_t>(index));
        entry_.script(index, canvas, random);
        canvas.finish(out);
    }

private:
    const Entry& entry_;
};

}  // namespace

Point Scene::init() const {
    SceneFrame first;
    render(0, first);
    return {first.truth.cx, first.truth.cy};
}

std::unique_ptr<Scene> make_scene(std::string_view name) {
    for (const Entry& entry : kCatalog)
        if (entry.name == name) return std::make_unique<ScriptedScene>(entry);
    return nullptr;
}

std::vector<std::string_view> scene_names() {
    std::vector<std::string_view> names;
    for (const Entry& entry : kCatalog) names.push_back(entry.name);
    return names;
}

}  // namespace rays::scenes
