// SPDX-License-Identifier: Apache-2.0
// Which places move with the target and which with the view: two motion layers (Wang & Adelson's
// layered motion, reduced to a target and a background). Between two frames the target moved by its
// own shift (matched on the contour's inside) and the view by the camera's (ViewMotion); a place on
// the target is explained by the first, a place on the background by the second. How much better
// one explains it than the other is the evidence, summed frame after frame into a log-odds map that
// moves with the target and forgets a tenth a frame. Where the two shifts are alike, or the image
// is plain, there is no evidence either way. This tells the target's extent from a contour round a
// part of it, where neither grey nor colour does (a patchy cow, a runner the camera follows), and
// unlike a learned background (BackgroundModel) it needs no still camera. The map is on the chroma grid of the colours'
// log-odds (LikelihoodMap), and the rays read the sum. Fixed memory; nothing allocated. An update
// costs some 25,000 samples (the shift's search, each cell before as either layer moved).
#pragma once
#include <array>

#include "core/appearance_model.hpp"
#include "core/contour.hpp"
#include "core/image.hpp"

namespace rays {

class MotionLayers {
public:
    static constexpr int kInsideSamples = 144;  // points inside the contour its shift is matched on

    void reset() { frames_ = 0; }
    // Whether the map holds evidence from enough frames to be read.
    bool valid() const;

    // Takes the evidence of a tracked frame: `now` and `before` are this frame and the previous one
    // (smoothed), `contour` this frame's, `moved_by` how far its centroid moved since the previous frame
    // and `view` how the view moved (this(x) = before(x − view)). The target's own shift is found
    // near `moved_by` by matching the contour's inside between the two frames.
    void update(const FloatImage& now, const FloatImage& before, const Contour& contour, Point moved_by, Point view);

    // Adds the map, moved on by `ahead` px (where the target is expected in the frame the map is
    // read for), to the log-odds in `map`, bounding the sum as the colours' are (naive Bayes: the
    // two cues taken as independent).
    void add_to(LikelihoodMap& map, Point ahead) const;
    // The same, but only where the map calls a place background (its negative log-odds): for a
    // source with no colours to tell the target's movers from others going its way, the layers say
    // where the scene is, never where the target is.
    void add_background_to(LikelihoodMap& map, Point ahead);

    Point target_shift() const { return shift_; }  // the last update's, px

private:
    // An inside sample's pixel cell and its bilinear fractions in the previous frame before any
    // shift: moved by a whole-pixel shift, only the cell moves.
    struct Tap {
        int x0 = 0, y0 = 0;
        float fx = 0.0f, fy = 0.0f;
    };
    using CellPlane = std::array<float, kChromaPixels>;

    // The target's shift between the frames, searched round `moved_by` and round the last shift.
    Point match_shift(const FloatImage& now, const FloatImage& before, const Contour& contour, Point moved_by);
    // Mean |now(x) − before(x − shift)| over the samples inside the contour, each from its tap: a
    // whole-pixel shift moves only the cell, any other the fractions too. Samples moved off the
    // image do not count.
    float inside_residual(const FloatImage& before, int dx, int dy) const;
    float inside_residual(const FloatImage& before, Point shift) const;
    // `image` at each cell's centre moved back by `shift` (this(x) = image(x − shift)); cells whose
    // sample falls off the image are marked in `off`.
    static void sample_cells(const FloatImage& image, Point shift, CellPlane& out, std::array<bool, kChromaPixels>& off);
    // The map moved on by `shift` px, each cell scaled by `keep` and added to `out` (0 off the map).
    void add_moved(Point shift, float keep, CellPlane& out) const;

    std::array<Tap, kInsideSamples> taps_{};
    std::array<float, kInsideSamples> inside_now_{};
    int inside_count_ = 0;
    LikelihoodMap map_;  // the log-odds as of the last update
    // This update's cells: now, and before moved each layer's way (then the residuals of the two).
    CellPlane here_{}, target_{}, view_{}, next_{};
    CellPlane moved_{};  // add_background_to()'s map moved on
    std::array<bool, kChromaPixels> target_off_{}, view_off_{};
    Point shift_;
    int frames_ = 0;
};

}  // namespace rays
