// SPDX-License-Identifier: Apache-2.0
// Where the target is, place by place, as the rays read it (a LikelihoodMap of log-odds on the chroma
// grid): the target's colours against its surroundings (AppearanceModel) and, while the view moves,
// where things move with the target rather than with the view (MotionLayers). On a grey source the
// layers alone, and only where they call a place the scene. Fixed memory; nothing allocated.
#pragma once
#include <optional>

#include "core/appearance_model.hpp"
#include "core/box.hpp"
#include "core/contour.hpp"
#include "core/image.hpp"
#include "core/motion_layers.hpp"
#include "core/view_motion.hpp"

namespace rays {

class TargetLikelihood {
public:
    // The terms' switches: rays.appearance_weight > 0 (`colours`) and rays.motion_layers (`layers`,
    // kept only with the colours' term on).
    void configure(bool colours, bool layers);
    // The frame being processed, its colour and the caller's word on how far the unit's turning moved
    // the view since the last capture (none: not said), for what follows until the next call.
    void begin_frame(const GreyImage& frame, const Chroma& chroma, std::optional<Point> expected_view);

    // A new target's first guess of its colours: round m surely the target (within `inside` px),
    // from `ring_from` to `ring_to` px mostly not; or a box's inside against a band `pad_px` wide
    // round it. False (nothing learned) on a grey source or with the term off.
    bool seed(Point m, double inside, double ring_from, double ring_to);
    bool seed_box(const Box& box, double pad_px);
    // Learns the colours from a tracked contour at `rate` (the first replaces them); false when the
    // frame has no colour, the term is off or the contour is too small.
    bool learn_colours(const Contour& contour, float rate);
    void forget_colours() { appearance_.reset(); }
    void forget_motion() { layers_.reset(); }
    const AppearanceModel& colours() const { return appearance_; }
    void restore_colours(const AppearanceModel& kept) { appearance_ = kept; }

    // This frame's map for the rays, or null when neither term has anything to say. The layers are
    // read only while `tracking` and the view moved between the last two frames tracked by their
    // rim; their map is moved on by `ahead`, the target's shift since the last frame.
    const LikelihoodMap* look(bool tracking, Point ahead);
    const LikelihoodMap& map() const { return map_; }

    // Whether the layers are kept: both terms on, and a colour source or a caller that says how the
    // unit's turning moved the view.
    bool layers_on() const;
    // After a frame tracked by its rim (`now`, smoothed; its contour moved by `moved_by` since the
    // previous frame): the layers learn from it where the view's shift is trusted — on a colour
    // source always, on a grey one where it agrees with the unit's turning.
    void learn_motion(const FloatImage& now, const Contour& contour, Point moved_by, ViewMotion& view_motion);
    // At the end of a frame: kept as the previous frame while the layers are on (only they read it).
    void keep_frame(const FloatImage& smoothed);

private:
    bool colours_on_ = true;
    bool layers_switch_ = true;
    const GreyImage* frame_ = nullptr;
    const Chroma* chroma_ = nullptr;
    std::optional<Point> expected_view_;
    AppearanceModel appearance_;  // the target's colours against its surroundings (colour sources)
    MotionLayers layers_;         // where things move with the target, not with the view
    bool view_moved_ = false;     // the view moved between the last two frames tracked by their rim
    LikelihoodMap map_;           // this frame's colours (and motion) seen through them
    FloatImage previous_;         // the previous frame (smoothed), for the layers ...
    bool has_previous_ = false;   // ... kept while they are on
};

}  // namespace rays
