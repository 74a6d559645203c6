// SPDX-License-Identifier: Apache-2.0
// A scene for the correlation filter's tests: a textured square on a differently textured
// background that pans, grey only or with colour. Its edges are everywhere; only its looks tell it
// apart.
#pragma once
#include <cmath>
#include <cstdint>
#include <memory>

#include "core/correlation_filter.hpp"
#include "core/gaussian_smoother.hpp"
#include "support/block_texture.hpp"

namespace rays::test {

// Background: 4-px blocks of random grey 40…200, moving with the pan. Target: a 20-px square of
// 3-px blocks of its own texture, moving with itself; `covered`: the background shows where it is.
struct TexturedScene {
    static constexpr int kHalf = 10;
    Point target{48.0, 60.0};
    Point pan;  // the background's offset

    void render(GreyImage& luma, Chroma& chroma, bool covered = false) const {
        const int bx = static_cast<int>(std::lround(pan.x)), by = static_cast<int>(std::lround(pan.y));
        const int tx = static_cast<int>(std::lround(target.x)), ty = static_cast<int>(std::lround(target.y));
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                const bool on = !covered && std::abs(x - tx) <= kHalf && std::abs(y - ty) <= kHalf;
                luma.at(x, y) = on ? static_cast<std::uint8_t>(40 + block_hash(floor_div(x - tx, 3), floor_div(y - ty, 3), 7u) % 161)
                                   : static_cast<std::uint8_t>(40 + block_hash(floor_div(x - bx, 4), floor_div(y - by, 4), 1u) % 161);
            }
        for (int j = 0; j < rays::kChromaSize; ++j)
            for (int i = 0; i < rays::kChromaSize; ++i) {
                const int x = 2 * i, y = 2 * j;
                const bool on = !covered && std::abs(x - tx) <= kHalf && std::abs(y - ty) <= kHalf;
                const std::uint32_t h = block_hash(floor_div(x - bx, 8), floor_div(y - by, 8), 3u);
                const auto k = static_cast<std::size_t>(j * rays::kChromaSize + i);
                chroma.u[k] = static_cast<std::uint8_t>(on ? 100 + h % 10 : 110 + h % 40);
                chroma.v[k] = static_cast<std::uint8_t>(on ? 170 + h % 10 : 100 + h % 40);
            }
    }
};

struct Images {
    GreyImage luma;
    Chroma chroma;
    FloatImage smoothed;
};

// Draws the scene and smooths it as the tracker does.
inline void draw(const TexturedScene& scene, Images& f, bool covered = false) {
    scene.render(f.luma, f.chroma, covered);
    rays::GaussianSmoother smoother;
    smoother.set_sigma(1.0);
    smoother.smooth(f.luma, f.smoothed);
}

// The scene drawn in colour, and a new filter learned on its target.
inline std::unique_ptr<CorrelationFilter> learned_on(const TexturedScene& scene, Images& f) {
    f.chroma.present = true;
    draw(scene, f);
    auto filter = std::make_unique<CorrelationFilter>();
    filter->learn(f.smoothed, f.chroma, scene.target, 2.0 * TexturedScene::kHalf, 1.0f);
    return filter;
}

}  // namespace rays::test
