// SPDX-License-Identifier: Apache-2.0
#include "core/chosen_target.hpp"

#include <cmath>

#include "core/target_model.hpp"

namespace rays {

void ChosenTarget::remember_start(double grey_share, const CorrelationFilter& filter) {
    start_grey_ = grey_share;
    start_looks_.copy_learned(filter);
}

void ChosenTarget::restore(const Standing& kept) {
    standing_ = kept.standing;
    start_grey_ = kept.start_grey;
}

bool ChosenTarget::found_again(const FloatImage& image, const Chroma& chroma, Point at, const Standing& kept) {
    if (start_looks_.locate(image, chroma, at).psr < CorrelationFilter::kConfidentPsr) return false;
    standing_ = true;
    start_grey_ = kept.start_grey;
    return true;
}

bool ChosenTarget::as_grey_as_at_start(double grey_share) const {
    return start_grey_ > 0.0 && std::abs(grey_share - start_grey_) <= TargetModel::kGreyTolerance;
}

bool ChosenTarget::vouches_for(const FloatImage& image, const Chroma& chroma, Point track, Point motion,
                               double match_psr, double grey_share) {
    if (!standing_ || match_psr < CorrelationFilter::kConfidentPsr || !as_grey_as_at_start(grey_share)) return false;
    const double here = start_looks_.locate(image, chroma, track).psr;
    const double there = start_looks_.locate(image, chroma, motion).psr;
    return there < CorrelationFilter::kConfidentPsr || there <= here;
}

}  // namespace rays
