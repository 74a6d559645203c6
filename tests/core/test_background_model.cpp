// SPDX-License-Identifier: Apache-2.0
// The still camera's background model: what it calls foreground, what it learns and forgets.
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "core/background_model.hpp"

namespace {

using rays::BackgroundModel;
using rays::FloatImage;
using rays::kFrameSize;

// A textured background (±20 grey) with a little per-frame noise, and a square of side 2·half at
// (cx, cy) `offset` grey levels off the background under it.
struct Scene {
    std::uint64_t state = 7;
    double noise() {  // uniform in [-1.5, 1.5]
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return 3.0 * static_cast<double>(state >> 11) / static_cast<double>(1ull << 53) - 1.5;
    }
    static double background(int x, int y) { return 110.0 + 20.0 * std::sin(0.35 * x) * std::cos(0.27 * y); }

    void render(FloatImage& out, double cx, double cy, double half, double offset) {
        for (int y = 0; y < kFrameSize; ++y)
            for (int x = 0; x < kFrameSize; ++x) {
                const bool in = std::abs(x - cx) <= half && std::abs(y - cy) <= half;
                out.at(x, y) = static_cast<float>(background(x, y) + (in ? offset : 0.0) + noise());
            }
    }
};

double mean_foreground(const FloatImage& f, int x0, int y0, int x1, int y1) {
    double sum = 0.0;
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) sum += f.at(x, y);
    return sum / ((x1 - x0 + 1) * (y1 - y0 + 1));
}

// A model and the frames it is shown.
struct Rig {
    Scene scene;
    std::unique_ptr<FloatImage> frame = std::make_unique<FloatImage>();
    BackgroundModel model;

    // Rates the scene's frame with the square at (cx, cy) (half < 0: none); the foreground, or null.
    const FloatImage* rate(double cx, double cy, double half, double offset) {
        scene.render(*frame, cx, cy, half, offset);
        model.rate(*frame);
        return model.foreground();
    }
    void learn() { model.learn(*frame, nullptr); }
    void show(double cx, double cy, double half, double offset) {
        rate(cx, cy, half, offset);
        learn();
    }
    void show_empty(int frames) {
        for (int i = 0; i < frames; ++i) show(0, 0, -1, 0.0);
    }
};

}  // namespace

TEST_CASE("BackgroundModel has no foreground until it has learned a few frames, nor after a reset", "[background]") {
    Rig rig;
    int first = -1;
    for (int i = 0; i < 20 && first < 0; ++i) {
        if (rig.rate(30, 30, 6, 0.0) != nullptr) first = i;
        rig.learn();
    }
    CHECK(first >= 5);  // a few frames learned first
    REQUIRE(first > 0);
    rig.model.reset();
    CHECK(rig.rate(30, 30, 6, 0.0) == nullptr);
}

TEST_CASE("BackgroundModel shows a square only 12 grey off a textured background as foreground", "[background]") {
    Rig rig;
    rig.show_empty(20);
    const FloatImage* f = rig.rate(64, 64, 10, -12.0);
    REQUIRE(f != nullptr);
    CHECK(rig.model.noise() < 2.0);
    CHECK(mean_foreground(*f, 56, 56, 72, 72) > 0.8);  // inside, clear of the rim
    CHECK(mean_foreground(*f, 0, 0, 127, 40) < 0.02);  // the background
}

TEST_CASE("BackgroundModel keeps no trail of a mover, and learns one that stopped", "[background]") {
    Rig rig;
    rig.show_empty(12);
    // A square crosses at 2 px/frame, no target box given (as before a track): where it was is
    // background again at once, the background under it never having been learned as the square.
    for (int i = 0; i < 30; ++i) rig.show(20 + 2 * i, 64, 8, -40.0);
    const FloatImage* f = rig.rate(80, 64, 8, -40.0);
    REQUIRE(f != nullptr);
    CHECK(mean_foreground(*f, 14, 56, 62, 72) < 0.02);  // its path
    CHECK(mean_foreground(*f, 74, 58, 86, 70) > 0.9);   // where it is
    // It stops there: after a while it is background too.
    int gone = -1;
    for (int i = 0; i < 60 && gone < 0; ++i) {
        f = rig.rate(80, 64, 8, -40.0);
        if (f != nullptr && mean_foreground(*f, 74, 58, 86, 70) < 0.05) gone = i;
        rig.learn();
    }
    INFO("learned after " << gone << " frames still");
    CHECK(gone >= 10);
    CHECK((gone > 0 && gone <= 25));
}

TEST_CASE("BackgroundModel says nothing of a frame unlike its background", "[background]") {
    Rig rig;
    rig.show_empty(12);
    CHECK(rig.rate(0, 0, -1, 0.0) != nullptr);
    for (float& v : rig.frame->px) v += 40.0f;  // a light switched on
    rig.model.rate(*rig.frame);
    CHECK(rig.model.foreground() == nullptr);
}
