// SPDX-License-Identifier: Apache-2.0
#include "core/target_likelihood.hpp"

#include <cmath>

namespace rays {
namespace {

constexpr double kViewAgreePx = 1.0;  // a view's measured shift within this of the unit's turning is the view's

}  // namespace

void TargetLikelihood::configure(bool colours, bool layers) {
    colours_on_ = colours;
    layers_switch_ = layers;
}

void TargetLikelihood::begin_frame(const GreyImage& frame, const Chroma& chroma, std::optional<Point> expected_view) {
    frame_ = &frame;
    chroma_ = &chroma;
    expected_view_ = expected_view;
}

bool TargetLikelihood::seed(Point m, double inside, double ring_from, double ring_to) {
    return colours_on_ && appearance_.seed(*frame_, *chroma_, m, inside, ring_from, ring_to);
}

bool TargetLikelihood::seed_box(const Box& box, double pad_px) {
    return colours_on_ && appearance_.seed_box(*frame_, *chroma_, box, pad_px);
}

bool TargetLikelihood::learn_colours(const Contour& contour, float rate) {
    return colours_on_ && appearance_.learn(*frame_, *chroma_, contour, rate);
}

const LikelihoodMap* TargetLikelihood::look(bool tracking, Point ahead) {
    const bool colours = colours_on_ && chroma_->present && appearance_.valid();
    const bool layers = layers_on() && view_moved_ && layers_.valid() && tracking;
    map_.split_rims = colours;
    if (colours) {
        appearance_.likelihood(*frame_, *chroma_, map_);
        // While the view moves, what moves with the target is the target too, whatever its colours
        // (motion_layers.hpp). On a still view the learned background tells movers from the scene,
        // and the layers would claim every other mover going the target's way (a crowd).
        if (layers) layers_.add_to(map_, ahead);
    } else if (layers) {
        // Grey: no colours tell the target from the other movers going its way (a crowd, a walker's
        // swinging legs), so the layers say only where the scene is. That is what cuts a contour
        // off a building it took in beside the walker the unit follows.
        map_.log_odds.fill(0.0f);
        layers_.add_background_to(map_, ahead);
    }
    return colours || layers ? &map_ : nullptr;
}

bool TargetLikelihood::layers_on() const {
    return layers_switch_ && colours_on_ && (chroma_->present || expected_view_.has_value());
}

void TargetLikelihood::learn_motion(const FloatImage& now, const Contour& contour, Point moved_by,
                                    ViewMotion& view_motion) {
    view_moved_ = false;
    if (!layers_on()) return;  // the view's shift is not worked out for nothing
    const ViewShift& view = view_motion.since_previous();
    // A grey source's layers take the view's measured shift only where the unit's own turning
    // accounts for it: a big mover can carry ViewMotion's bands with it in a still view, and a fast
    // turn moves the view beyond what they measure (colours outweigh such a frame's evidence; grey
    // has nothing else).
    const bool trusted = chroma_->present ||
                         (expected_view_ && std::abs(view.shift.x - expected_view_->x) <= kViewAgreePx &&
                          std::abs(view.shift.y - expected_view_->y) <= kViewAgreePx);
    view_moved_ = view.known && !view.still && trusted;
    if (has_previous_ && view.known && trusted) layers_.update(now, previous_, contour, moved_by, view.shift);
}

void TargetLikelihood::keep_frame(const FloatImage& smoothed) {
    has_previous_ = layers_on();
    if (has_previous_) previous_ = smoothed;
}

}  // namespace rays
