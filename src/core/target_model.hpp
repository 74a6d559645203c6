// SPDX-License-Identifier: Apache-2.0
// What the tracker has learned of its target from earlier contours, for the terms beyond the
// paper's edge energy: edge polarity, the 1-D region term and the contrast that normalises eq. 7.
#pragma once
#include <array>
#include <vector>

#include "core/box.hpp"
#include "core/contour.hpp"

namespace rays {

struct TargetModel {
    static constexpr int kBins = 32;  // angular bins round the target
    // Two insides whose mean grey differs by at most this share of the frame's mean grey look alike.
    static constexpr double kGreyTolerance = 0.15;

    bool valid = false;
    std::array<float, kBins> polarity{};     // mean sign of dρ/dλ at the rim, −1 … 1
    std::array<float, kBins> inside_mean{};  // grey level inside, looking along that direction
    std::array<float, kBins> outside_mean{}; // grey level just outside the rim there (< 0: not seen yet)
    float inside_spread = 0;                 // typical grey deviation inside
    float rim_contrast = 0;                  // median |dρ/dλ| on the rim, grey/px
    float frame_mean = 0;                    // the frame's mean grey the grey levels above belong to

    static int bin(float phi);
    void reset() { valid = false; }
    // A first guess before any contour: the target looks like the image round its start point
    // (mean grey of a 5×5 patch at m); no polarity yet.
    void seed(const FloatImage& image, Point m);
    // A box start's first guess (core/box.hpp): the target looks like the image inside the box's
    // inscribed ellipse, clear of its rim — grey per direction round the centre, and its spread.
    void seed_inside(const FloatImage& image, const Box& box);
    // Learns from a contour; `scratch` holds max_rays floats (no allocation).
    void learn(const Contour& contour, std::vector<float>& scratch);
    // The whole frame's mean grey is now `mean`: when it jumped from the last frame's (an exposure
    // step), the learned grey levels and contrasts scale with it, so the target still looks itself.
    void follow_exposure(float mean);
};

}  // namespace rays
