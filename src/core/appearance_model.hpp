// SPDX-License-Identifier: Apache-2.0
// What the target looks like against the background round it, in colour: two histograms over
// quantised (Y, Cb, Cr), one of the target's inside and one of a ring of background round it,
// learned from tracked contours and blended over frames (the colour learner of Staple, Bertinetto et
// al., CVPR 2016). From them each place gets P(target | its colour) by Bayes' rule with equal priors,
// on a 64×64 grid aligned with the chroma (one cell = one chroma pixel = 2×2 processing pixels). The
// rays read that map as a second 1-D signal beside the grey profile (ray_hypotheses.hpp): a rim is
// where the likelihood falls, not merely where grey changes. A mono source has no colour to learn:
// the model stays empty and the rays use grey alone. Fixed memory, copied as a whole; nothing
// allocated.
#pragma once
#include <algorithm>
#include <array>

#include "core/box.hpp"
#include "core/contour.hpp"
#include "core/image.hpp"

namespace rays {

// The log-odds log(P(target | colour) / P(background | colour)) per chroma cell, bounded by
// ±kMaxLogOdds (no colour is ever certain). Cell (i, j) is centred on processing pixel (2i + 0.5, 2j + 0.5).
struct LikelihoodMap {
    static constexpr int kSize = kChromaSize;
    static constexpr float kMaxLogOdds = 3.0f;  // P = 0.95
    std::array<float, kChromaPixels> log_odds{};
    // Whether a ray's split may stand as a rim where no edge is near it (the colours'); false where
    // the map only says where the scene is (a grey source's motion layers), which moves a ray's
    // choice among its edges but makes no rim where grey shows none.
    bool split_rims = true;

    float cell(int i, int j) const { return log_odds[static_cast<std::size_t>(j * kSize + i)]; }
    // Bilinear between cell centres at processing pixel (x, y); clamped at the border. Inline: the
    // rays read it at every sample.
    float at(float x, float y) const {
        const float u = std::clamp((x - 0.5f) * 0.5f, 0.0f, kSize - 1.0f);
        const float v = std::clamp((y - 0.5f) * 0.5f, 0.0f, kSize - 1.0f);
        const int i = std::min(static_cast<int>(u), kSize - 2), j = std::min(static_cast<int>(v), kSize - 2);
        const float fx = u - static_cast<float>(i), fy = v - static_cast<float>(j);
        const float* r0 = &log_odds[static_cast<std::size_t>(j * kSize + i)];
        const float* r1 = r0 + kSize;
        const float top = r0[0] + fx * (r0[1] - r0[0]);
        const float bottom = r1[0] + fx * (r1[1] - r1[0]);
        return top + fy * (bottom - top);
    }
};

class AppearanceModel {
public:
    static constexpr int kLumaBits = 4;    // 16 grey levels ...
    static constexpr int kChromaBits = 3;  // ... × 8 × 8 colours
    static constexpr int kBins = 1 << (kLumaBits + 2 * kChromaBits);

    void reset() { valid_ = false; }
    bool valid() const { return valid_; }

    // Learns the contour's inside as the target and a ring round it (as wide as the target's
    // equivalent radius, clear of the rim by a cell) as the background, each cell once, blended into
    // the model with weight `rate` (the first contour after reset() replaces it). False, and nothing
    // learned, for a mono frame or a contour too small to learn from.
    bool learn(const GreyImage& luma, const Chroma& chroma, const Contour& contour, float rate);

    // A first guess before any contour, from a point known to lie on the target: the cells within
    // `inside_px` of it are the target, those from `ring_from_px` to `ring_to_px` away the background
    // (much of which may be target too: such colours come out near even, which says nothing either
    // way). Replaces the model; false for a mono frame or too few cells.
    bool seed(const GreyImage& luma, const Chroma& chroma, Point centre, double inside_px, double ring_from_px,
              double ring_to_px);

    // A first guess from a box round the target (Staple's): the cells inside the box are the target,
    // those in a band `pad_px` wide round it the background. What the box holds beside the target
    // (its corners, a gap under an arm) is as common round it, so its colours come out near even.
    // Replaces the model; false for a mono frame or too few cells.
    bool seed_box(const GreyImage& luma, const Chroma& chroma, const Box& box, double pad_px);
    // The log-odds of every cell of the frame. Call only while valid(). Not const: a bin's log-odds
    // is worked out from the histograms when a frame first shows its colour (most of the 1024
    // colours are in no frame), and kept until the model learns again.
    void likelihood(const GreyImage& luma, const Chroma& chroma, LikelihoodMap& out);

private:
    static int bin(const GreyImage& luma, const Chroma& chroma, int i, int j);
    // Replaces the model with the cells `place(x, y)` (a cell's centre, processing pixels) calls the
    // target (> 0) against those it calls the background (< 0).
    template <typename Place>
    bool seed_where(const GreyImage& luma, const Chroma& chroma, Place place);
    // Takes new_target_ and new_background_ (counts) into the model at `rate`.
    bool blend(int targets, int backgrounds, float rate);
    // Bin b's log-odds, worked out if not yet known since the last blend.
    float log_odds(int b);
    // Marks the cells whose centres lie inside the contour, within rows j0 … j1 (even-odd rule).
    void fill_inside(const Contour& contour, int j0, int j1);

    std::array<float, kBins> target_{}, background_{};  // each sums to 1
    std::array<float, kBins> log_odds_{};               // per bin, from the two ...
    std::array<bool, kBins> odds_known_{};              // ... where known since the last blend
    std::array<float, kBins> new_target_{}, new_background_{};
    std::array<unsigned char, kChromaPixels> inside_{};
    // Each scan line's crossings of the contour; a line that crosses it more often (a contour jagged
    // beyond any target's) is filled as far as these reach.
    static constexpr int kMaxCrossings = 64;
    std::array<float, kChromaSize * kMaxCrossings> crossings_{};
    std::array<int, kChromaSize> crossing_count_{};
    bool valid_ = false;
};

}  // namespace rays
