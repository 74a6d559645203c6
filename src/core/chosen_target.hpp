// SPDX-License-Identifier: Apache-2.0
// What a person's choice of target says beyond its first contour: whether the track now is the
// person's target, and how that target looked at its start — the correlation filter as learned on
// the first contour (never learned since, so it does not drift with the contour) and the grey the
// contour enclosed. With these, a track standing still that the motion detector doubts is kept
// while it is still the person's target, and a mover the detector finds after a loss is known
// again as that target. Fixed memory; nothing allocated.
#pragma once

#include "core/correlation_filter.hpp"
#include "core/image.hpp"

namespace rays {

class ChosenTarget {
public:
    // A person chose a target (Tracker::start_at, start_in), or none since reinit().
    void choose() { chosen_ = true; }
    void forget_choice() { chosen_ = false; }
    // Whether a person chose the target since the last reinit(), whoever found it last: the
    // detector then looks for it at its own size.
    bool chosen() const { return chosen_; }

    // Whether the track now is the person's target.
    bool standing() const { return standing_; }
    // A new target's track, from a person's start or not (a re-acquisition keeps the standing).
    void begin(bool by_person) { standing_ = by_person; }

    // The person's target's first contour: the grey it encloses (over the frame's mean grey) and
    // the filter learned on it.
    void remember_start(double grey_share, const CorrelationFilter& filter);
    // A mover the detector found, as a new target: it has no start to be compared with.
    void forget_start_grey() { start_grey_ = 0.0; }

    // The standing and the start's grey before a detector's start that may turn out to be the
    // person's target (for found_again(), or restore() where the start failed).
    struct Standing {
        bool standing = false;
        double start_grey = 0.0;
    };
    Standing standing_now() const { return {standing_, start_grey_}; }
    void restore(const Standing& kept);
    // A detector's new track at `at` (the standing was `kept` before it): true, and the person's
    // target with its start's grey again, where the start's looks find the target there surely.
    bool found_again(const FloatImage& image, const Chroma& chroma, Point at, const Standing& kept);

    // Whether a contour enclosing `grey_share` (its inside grey over the frame's mean) is about as
    // grey as the person's target was at its start.
    bool as_grey_as_at_start(double grey_share) const;

    // Whether a track at `track` that the motion detector doubts (its mover at `motion`, away from
    // the track) is still the person's target: the filter finds it surely there (`match_psr`), it
    // is as grey as at the start, and the start's looks find the target there at least as clearly
    // as where the motion is.
    bool vouches_for(const FloatImage& image, const Chroma& chroma, Point track, Point motion, double match_psr,
                     double grey_share);

private:
    bool chosen_ = false;
    bool standing_ = false;
    double start_grey_ = 0.0;   // the start's inside grey over the frame's mean (0: none)
    CorrelationFilter start_looks_;
};

}  // namespace rays
