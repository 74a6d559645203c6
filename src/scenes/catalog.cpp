// The scenes: each a fixed script of background, target path and disturbances.
#include <cmath>
#include <functional>
#include <numbers>

#include "scenes/render.hpp"

namespace rays::scenes {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

using Script = std::function<void(int, Canvas&, Random&)>;

class ScriptedScene final : public Scene {
public:
    ScriptedScene(std::string_view name, std::string_view description, int frames, std::uint64_t seed, Script script)
        : name_(name), description_(description), frames_(frames), seed_(seed), script_(std::move(script)) {}
    std::string_view name() const override { return name_; }
    std::string_view description() const override { return description_; }
    int frame_count() const override { return frames_; }
    void render(int index, SceneFrame& out) const override {
        Canvas canvas;
        Random random(seed_ * 1000003ull + static_cast<std::uint64_t>(index));
        script_(index, canvas, random);
        canvas.finish(out);
    }

private:
    std::string_view name_, description_;
    int frames_;
    std::uint64_t seed_;
    Script script_;
};

// Position along a back-and-forth run between lo and hi after travelling `distance`.
double bounce(double lo, double hi, double distance) {
    const double span = hi - lo, d = std::fmod(distance, 2 * span);
    return d < span ? lo + d : hi - (d - span);
}

// Distance travelled by frame t: speed ramps 2 → 8 px/frame over 170 frames, holds 8 for 60 frames,
// then ramps 8 → 16 px/frame by frame 399.
double ramp_distance(int t) {
    double d = 0;
    for (int i = 0; i < t; ++i) d += i < 170 ? 2.0 + 6.0 * i / 170.0 : i < 230 ? 8.0 : 8.0 + 8.0 * (i - 230) / 169.0;
    return d;
}

std::unique_ptr<Scene> build(std::string_view name) {
    if (name == "disc")
        return std::make_unique<ScriptedScene>("disc", "a bright disc on a dark plain background, circling at 1.5 px/frame",
            300, 1, [](int t, Canvas& c, Random& r) {
                c.fill(50);
                const double a = kTwoPi * t / 120.0;
                c.paint(Ellipse{64 + 28 * std::cos(a), 64 + 28 * std::sin(a), 14, 14}, 200, true);
                c.noise(3, r);
            });
    if (name == "vanish")
        return std::make_unique<ScriptedScene>("vanish", "a disc that moves, disappears for 40 frames and comes back elsewhere",
            300, 2, [](int t, Canvas& c, Random& r) {
                c.fill(50);
                if (t < 60) c.paint(Ellipse{30 + 1.5 * t, 40, 13, 13}, 200, true);
                if (t >= 100) c.paint(Ellipse{100 - 1.2 * (t - 100) * 0.3, 90 - 0.2 * (t - 100), 13, 13}, 200, true);
                c.noise(3, r);
            });
    if (name == "clutter")
        return std::make_unique<ScriptedScene>("clutter", "a bright ellipse over random rectangles and lines with strong edges",
            300, 3, [](int t, Canvas& c, Random& r) {
                c.texture(110, 20, 24, 3);
                Random layout(33);
                for (int k = 0; k < 14; ++k) {
                    const double x = layout.uniform() * 120, y = layout.uniform() * 120;
                    const double w = 4 + layout.uniform() * 26, h = 4 + layout.uniform() * 26;
                    c.rect(x, y, x + (k % 3 == 0 ? 2 : w), y + (k % 3 == 1 ? 2 : h), 60 + layout.uniform() * 140);
                }
                const double a = kTwoPi * t / 150.0;
                c.paint(Ellipse{64 + 34 * std::sin(a), 64 + 26 * std::sin(2 * a + 0.5), 14, 10, 0.3 * std::sin(a)}, 205, true);
                c.noise(4, r);
            });
    if (name == "star")
        return std::make_unique<ScriptedScene>("star", "a rotating concave five-pointed star drifting over a textured background",
            300, 4, [](int t, Canvas& c, Random& r) {
                c.texture(100, 25, 16, 4);
                const double a = kTwoPi * t / 200.0;
                c.paint(Star{64 + 30 * std::sin(a), 64 + 22 * std::cos(1.5 * a), 22, 10, 5, 0.03 * t}, 190, true);
                c.noise(4, r);
            });
    if (name == "walker-pole")
        return std::make_unique<ScriptedScene>("walker-pole", "a dark walking silhouette passing in front of a dark pole",
            300, 5, [](int t, Canvas& c, Random& r) {
                c.texture(150, 15, 20, 5);
                c.rect(70, 0, 74, 127, 60);
                const double x = 64 + 44 * std::sin(kTwoPi * t / 280.0);
                c.paint(Walker{x, 66, 52, 0.35 * t}, 55, true);
                c.noise(4, r);
            });
    if (name == "weak-contrast")
        return std::make_unique<ScriptedScene>("weak-contrast", "a target 18 grey levels above its surround, near stronger background edges",
            300, 6, [](int t, Canvas& c, Random& r) {
                c.texture(100, 6, 20, 6);
                c.rect(10, 10, 40, 50, 155);
                c.rect(88, 70, 120, 118, 45);
                c.rect(50, 96, 80, 102, 160);
                const double a = kTwoPi * t / 160.0;
                c.paint(Ellipse{64 + 30 * std::sin(a), 62 + 22 * std::sin(2 * a), 13, 11}, 118, true);
                c.noise(3, r);
            });
    if (name == "shadow")
        return std::make_unique<ScriptedScene>("shadow", "a bright blob crossing a strong diagonal sunlight/shadow border",
            300, 7, [](int t, Canvas& c, Random& r) {
                c.texture(150, 15, 20, 7);
                const double x = 64 + 44 * std::sin(kTwoPi * t / 300.0 - 1.2);
                c.paint(Ellipse{x, 64 + 10 * std::sin(kTwoPi * t / 150.0), 12, 10}, 215, true);
                c.multiply_half_plane(0.8, -0.6, 20, 0.45);
                c.noise(4, r);
            });
    if (name == "occluder")
        return std::make_unique<ScriptedScene>("occluder", "an ellipse passing behind a dark vertical bar",
            300, 8, [](int t, Canvas& c, Random& r) {
                c.texture(100, 15, 20, 8);
                const double x = 64 + 44 * std::sin(kTwoPi * t / 200.0);
                c.paint(Ellipse{x, 64, 13, 10}, 195, true);
                c.occlude(60, 0, 67, 127, 35);
                c.noise(4, r);
            });
    if (name == "speed-ramp")
        return std::make_unique<ScriptedScene>("speed-ramp", "an ellipse running back and forth, speed ramping from 2 to 16 px/frame",
            400, 9, [](int t, Canvas& c, Random& r) {
                c.texture(90, 15, 20, 9);
                c.paint(Ellipse{bounce(20, 108, ramp_distance(t)), 64, 11, 9}, 200, true);
                c.noise(4, r);
            });
    if (name == "noise-blur")
        return std::make_unique<ScriptedScene>("noise-blur", "a medium-contrast ellipse under heavy noise and blur",
            300, 10, [](int t, Canvas& c, Random& r) {
                c.texture(100, 10, 24, 10);
                const double a = kTwoPi * t / 160.0;
                c.paint(Ellipse{64 + 32 * std::cos(a), 64 + 24 * std::sin(a), 15, 12}, 160, true);
                c.blur3();
                c.noise(20, r);
            });
    if (name == "approach")
        return std::make_unique<ScriptedScene>("approach", "a walker approaching the camera, growing threefold",
            300, 11, [](int t, Canvas& c, Random& r) {
                c.texture(150, 15, 20, 11);
                const double h = 25 + 50 * t / 299.0;
                c.paint(Walker{64 + 25 * std::sin(kTwoPi * t / 150.0), 64, h, 0.3 * t}, 55, true);
                c.noise(4, r);
            });
    return nullptr;
}

}  // namespace

Point Scene::init() const {
    SceneFrame f;
    render(0, f);
    return {f.truth.cx, f.truth.cy};
}

std::unique_ptr<Scene> make_scene(std::string_view name) { return build(name); }

std::vector<std::string_view> scene_names() {
    return {"disc", "vanish", "clutter", "star", "walker-pole", "weak-contrast", "shadow", "occluder", "speed-ramp",
            "noise-blur", "approach"};
}

}  // namespace rays::scenes
