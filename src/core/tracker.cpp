// SPDX-License-Identifier: Apache-2.0
#include "core/tracker.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rays {
namespace {

constexpr double kStartRadiusPx = 10.0;  // least first guess of the contour size at a new target
constexpr int kStartCandidates = 6;     // start points tried round a detected region's centre
constexpr double kVelocityRate = 0.7;     // weight of the newest centroid step in the velocity
constexpr double kRetryMinSpeedPx = 1.0;  // slower targets are not worth a second prediction
constexpr double kReacquireAreaRatio = 0.3;  // a fresh re-acquisition's area within this factor of the lost
                                             // contour's (or above, of the whole target's), either way ...
constexpr int kFreshReacquireFrames = 10;    // ... and only this soon after the loss (a target in passing
                                             // behind something thin, not one that is gone)
constexpr double kReacquireSideShift = 0.6;  // of the target's radius: the points beside a hidden middle
constexpr float kColourRate = 0.1f;      // weight of the newest contour in the learned colours (Staple: 0.04)
constexpr double kSeedInside = 0.3;      // of a new target's radius: surely the target round its start point
constexpr double kSeedRingFrom = 2.0;    // ... and from this many radii ...
constexpr double kSeedRingTo = 3.0;      // ... to this many, mostly not
constexpr double kBoxBand = 0.15;        // of a box's longer side: the band round it whose colours are background
constexpr float kFilterRate = 0.02f;     // weight of the newest frame in the correlation filter (CSRT: 0.02)
constexpr double kRedetectShare = 0.5;  // of the target's mean PSR while tracked: what a match found
                                        // elsewhere in the frame must reach (a textured background
                                        // gives 5–8 here and there; real targets 9–48, median)
constexpr double kPsrRate = 0.1;        // weight of the newest frame in that mean
constexpr double kFilterAgreement = 1.0; // of the target's radius: a contour whose centroid is further from
                                         // a confident filter match has left the target

}  // namespace

Tracker::Tracker(const TrackerConfig& config, const Clock& clock)
    : clock_(clock),
      capacity_(config.capacity),
      rays_(config.capacity),
      prior_(config.capacity.max_rays),
      contour_(config.capacity),
      last_points_(config.capacity.max_rays),
      last_open_(config.capacity.max_rays),
      scratch_(config.capacity.max_rays) {
    set_tunables(config.tunables);
    detector_.reset(tunables_.detect);
}

bool Tracker::set_tunables(const TrackerTunables& tunables) {
    if (!rays_.configure(tunables.rays)) {
        rays_.configure(tunables_.rays);  // keep the previous, valid settings
        return false;
    }
    tunables_ = tunables;
    smoother_.set_sigma(tunables_.rays.sigma_px);
    likelihood_.configure(tunables_.rays.appearance_weight > 0.0, tunables_.rays.motion_layers);
    return true;
}

void Tracker::start_at(Point m) {
    chosen_.choose();
    start_point_ = m;
    start_box_.reset();
    reacquire_ = false;
}

bool Tracker::start_in(const Box& box) {
    if (box_problem(box) != nullptr) return false;
    start_point_ = box.centre();
    start_box_ = box;
    chosen_.choose();
    reacquire_ = false;
    return true;
}

void Tracker::reacquire_at(Point m) {
    start_point_ = m;
    start_box_.reset();
    reacquire_ = true;
}

void Tracker::allow_detection(bool allowed) { detection_allowed_ = allowed; }

void Tracker::release() {
    result_.state = TrackState::Detecting;
    result_.has_contour = false;
    start_point_.reset();
    start_box_.reset();
}

void Tracker::reinit() {
    release();
    chosen_.forget_choice();
    detector_.reset(tunables_.detect);
}


void Tracker::look_with_likelihood(Point ahead) {
    rays_.use_likelihood(likelihood_.look(result_.state == TrackState::Tracking, ahead));
}

void Tracker::use_seeded_colours(bool seeded) {
    if (seeded) look_with_likelihood();
    else forget_colours();
}

void Tracker::forget_colours() {
    likelihood_.forget_colours();
    rays_.use_likelihood(nullptr);
}

void Tracker::remember_contour() {
    tracked_area_ = std::max(0.0, contour_.area);
    // What the target looks like whole: an occluder in front of part of it does not get learned here.
    if (whole_area_.shows_whole(tracked_area_) && model_.frame_mean > 0.0f) {
        const double grey = mean_inside_grey(contour_) / model_.frame_mean;
        whole_grey_ = whole_grey_ <= 0.0 ? grey : whole_grey_ + whole_area_.rate() * (grey - whole_grey_);
    }
    whole_area_.update(tracked_area_);
    last_seen_ = contour_.centroid;
    last_count_ = contour_.size;
    for (int i = 0; i < last_count_; ++i) {
        last_points_[i] = contour_.points[i].p;
        last_open_[i] = contour_.points[i].no_edge;
    }
}

Point Tracker::best_start(Point centre, double radius, TimePoint deadline) {
    // Frame differencing often finds only a rim of the object (the crescents a slow, uniform object
    // leaves), so m may start on the rim. Coarse contours from the region's centre and from points
    // round it are compared; the most object-like one that still holds the moving region's centre
    // gives the start.
    Point best = centre;
    double best_score = 0.0;
    const double d = std::max(radius, kStartRadiusPx * 0.6);
    for (int k = -1; k < kStartCandidates; ++k) {
        const double a = 2.0 * std::numbers::pi * k / kStartCandidates;
        const Point m = k < 0 ? centre : Point{centre.x + d * std::cos(a), centre.y + d * std::sin(a)};
        model_.seed(smoothed_, m);
        rays_.extract(smoothed_, m, prior_, false, model_, clock_, deadline, contour_, 0);
        const double score = contour_contains(contour_, centre) ? contour_objectness(contour_) : 0.0;
        if (score > best_score) {
            best_score = score;
            best = contour_.centroid;
        }
    }
    return best;
}

bool Tracker::begin_track(Point m, double radius, StartFrom from, bool same_target, TimePoint deadline,
                          double max_area) {
    if (!same_target) {
        model_.reset();
        likelihood_.forget_motion();
        forget_colours();
        if (from != StartFrom::Prediction) chosen_.begin(from == StartFrom::Person);  // a re-acquisition keeps it
    }
    prior_.set_circle(std::max(radius, kStartRadiusPx));
    if (from == StartFrom::Detector) m = best_start(m, radius, deadline);
    if (!same_target) {
        model_.seed(smoothed_, m);
        // Round m is the target, further out mostly not: where that tells colours apart, the first
        // rays find where the target's colours end even where grey shows no edge there.
        radius = std::max(radius, kStartRadiusPx);
        use_seeded_colours(likelihood_.seed(m, kSeedInside * radius, kSeedRingFrom * radius, kSeedRingTo * radius));
    }
    return first_contour(m, from, same_target, deadline, max_area);
}

bool Tracker::begin_box_track(const Box& box, TimePoint deadline) {
    // The box is the target's extent: the contour is expected on its inscribed ellipse, the rays
    // search from part of the way to it to a little beyond the box's border, and the target looks
    // like the box's inside (PolarPrior::set_box, TargetModel::seed_inside).
    prior_.set_box(box);
    model_.reset();
    likelihood_.forget_motion();
    chosen_.begin(true);
    model_.seed_inside(smoothed_, box);
    // The box holds the target, a band round it does not: what the box holds beside the target
    // (its corners) is as common round it, so its colours come out near even (Staple's seed).
    use_seeded_colours(likelihood_.seed_box(box, kBoxBand * std::max(box.w, box.h)));
    // The box's centre need not lie on the target (core/box_start.hpp).
    const Point m = likelihood_.colours().valid() ? box_start_.find(box, likelihood_.map()) : box.centre();
    return first_contour(m, StartFrom::Person, false, deadline);
}

bool Tracker::first_contour(Point m, StartFrom from, bool same_target, TimePoint deadline, double max_area) {
    attention_.reset();
    velocity_ = {};
    // A person's start is the target even where few rays find an edge on it (a target about as grey
    // as what is round it): the contour holds the prior there, and the track begins.
    AttentionTunables limits = tunables_.attention;
    if (from == StartFrom::Person) limits.max_none_fraction = 1.0;
    rays_.extract(smoothed_, m, prior_, false, model_, clock_, deadline, contour_);
    const char* reason = attention_.check(contour_, contour_.centroid, limits);
    if (reason != nullptr && !same_target && likelihood_.colours().valid()) {
        // The seeded colours did not make a target of it: grey alone, as without colour.
        forget_colours();
        rays_.extract(smoothed_, m, prior_, false, model_, clock_, deadline, contour_);
        reason = attention_.check(contour_, contour_.centroid, limits);
    }
    // A person's point is on the target: a contour that has moved off it is of something beside it;
    // the contour seen from the point itself is the target's. So is it where most rays found no edge
    // (more than a tracked contour may have): that contour is mostly the prior, and its centre of
    // gravity (eq. 11) is where the few edges found pull it, not the target's. (A box's centre need
    // not be on the target.)
    const bool mostly_prior = contour_.no_edge_rays > tunables_.attention.max_none_fraction * contour_.size;
    if (from == StartFrom::Person && !start_box_ && (!contour_contains(contour_, m) || mostly_prior)) {
        rays_.extract(smoothed_, m, prior_, false, model_, clock_, deadline, contour_, -1, false);
        attention_.reset();  // the contour it replaces is no previous frame's
        reason = attention_.check(contour_, contour_.centroid, limits);
    }
    // The same target found again is about its own size, not the block or group beside it.
    if (same_target) max_area = reacquire_bound();
    if (reason == nullptr && max_area > 0.0 && contour_.area > max_area) reason = "much bigger than the target";
    if (reason != nullptr) return false;
    if (!same_target) {
        model_.reset();
        whole_area_.reset();
        whole_grey_ = 0.0;
    }
    // The first contour is blended into the seed's colours like any tracked frame's: it may have
    // run out onto background the seed has told apart (the first contour of a new model replaces it).
    likelihood_.learn_colours(contour_, kColourRate);
    // A fresh re-acquisition (reacquire_afresh) keeps the filter until it is known to be the target.
    if (from != StartFrom::Prediction || same_target) learn_looks(same_target ? kFilterRate : 1.0f, from == StartFrom::Filter);
    if (!same_target && from != StartFrom::Prediction) psr_tracked_ = 0.0;
    model_.learn(contour_, scratch_);
    // A person's target as it looked at the start: the learned looks drift with the contour, this does not.
    if (from == StartFrom::Person && !same_target) chosen_.remember_start(inside_grey_share(), filter_);
    if (from == StartFrom::Detector) chosen_.forget_start_grey();
    remember_contour();
    return true;
}

bool Tracker::reacquire_afresh(Point m, double radius, TimePoint deadline) {
    // What kept the learned looks from finding the target (it is coming out from behind something
    // and shows only part of itself) may let a fresh start find it; a fresh start finds anything, so
    // it must look like the target did: about as grey inside, about as big.
    const TargetModel kept = model_;
    const AppearanceModel kept_colours = likelihood_.colours();
    const double area = tracked_area_;
    const WholeArea whole = whole_area_;
    const double whole_grey = whole_grey_;
    const Point seen = last_seen_;
    const double bound = reacquire_bound();
    if (!kept.valid) return false;
    const bool found = begin_track(m, radius, StartFrom::Prediction, false, deadline);
    auto mean_inside = [](const TargetModel& model) {
        float sum = 0.0f;
        for (float v : model.inside_mean) sum += v;
        return sum / static_cast<float>(TargetModel::kBins);
    };
    // As grey as the learned looks, or as the target was when last seen whole (the learned looks may
    // hold some of what hid part of it).
    const double frame = std::max<double>(kept.frame_mean, 1.0);
    const double was = mean_inside(kept), now = mean_inside(model_);
    const bool grey_alike = std::abs(now - was) <= TargetModel::kGreyTolerance * frame ||
                            (whole_grey > 0.0 && std::abs(now / frame - whole_grey) <= TargetModel::kGreyTolerance);
    const bool alike = found && grey_alike && contour_.area >= kReacquireAreaRatio * area && contour_.area <= bound;
    whole_area_ = whole;  // the same target, if alike
    whole_grey_ = whole_grey;
    if (alike) learn_looks(kFilterRate, false);
    if (!alike) {  // not the target: as if it had not been tried
        model_ = kept;
        likelihood_.restore_colours(kept_colours);
        look_with_likelihood();
        tracked_area_ = area;
        last_seen_ = seen;  // where the filter looks for it again
    }
    return alike;
}

bool Tracker::begin_detected(const Detection& d, TimePoint deadline) {
    // A person's target, once lost, is looked for at its own size: a mover whose contour is much
    // bigger (the group that holds it, the background a pan sweeps past a runner) is not it. That
    // holds too once the detector has found again a mover that kept no person's standing: it was
    // taken, at that size, for the person's target.
    const double bound = chosen_.chosen() ? reacquire_bound() : 0.0;
    if (bound <= 0.0) return begin_track(d.centre, d.radius_px, StartFrom::Detector, false, deadline);
    const TargetModel kept = model_;
    const AppearanceModel kept_colours = likelihood_.colours();
    const ChosenTarget::Standing standing = chosen_.standing_now();
    if (begin_track(d.centre, d.radius_px, StartFrom::Detector, false, deadline, bound)) {
        // A mover that looks as the person's target did at the start is that target found again: it
        // keeps the person's standing (the watch's exemption, the grey at the start).
        chosen_.found_again(smoothed_, *chroma_, contour_.centroid, standing);
        return true;
    }
    model_ = kept;  // not the target: its learned looks are still what the filter looks for
    likelihood_.restore_colours(kept_colours);
    look_with_likelihood();
    chosen_.restore(standing);
    return false;
}

void Tracker::learn_looks(float rate, bool located, const Point* at) {
    const double diameter = 2.0 * std::sqrt(std::max(contour_.area, 1.0) / std::numbers::pi);
    const Point centre = at ? *at : contour_.centroid;
    if (located) filter_.learn_located(smoothed_, *chroma_, centre, diameter, rate);
    else filter_.learn(smoothed_, *chroma_, centre, diameter, rate);
}

void Tracker::track(TimePoint deadline) {
    const Point last = contour_.centroid;
    Point v = tunables_.predict ? velocity_ : Point{};
    // The correlation filter, where it is sure, says where the target is, edges or not.
    const Point expected = external_prediction_ ? *external_prediction_ : Point{last.x + v.x, last.y + v.y};
    match_ = filter_.locate(smoothed_, *chroma_, expected);
    result_.match_psr = match_.psr;
    const bool confident = match_.psr >= CorrelationFilter::kConfidentPsr;
    if (confident) v = {match_.at.x - last.x, match_.at.y - last.y};
    // Where a confident filter match says the target is, once: a measurement, not a guess. Without
    // one, constant velocity first; when that contour fails the attention check (the target turned
    // or stopped), the target held still, then reversed — a turn must not cost the track. Without a
    // confident match, an outside prediction (predict_next: the unit's own motion taken out) goes
    // first, with the image's own constant velocity as the fallback.
    Point steps[] = {v, {0.0, 0.0}, {-v.x, -v.y}};
    int tries = !confident && std::hypot(v.x, v.y) >= kRetryMinSpeedPx ? 3 : 1;
    if (external_prediction_ && !confident) {
        steps[2] = steps[0];
        steps[0] = {external_prediction_->x - last.x, external_prediction_->y - last.y};
        steps[1] = {0.0, 0.0};
        tries = 3;
    }
    Point applied{};
    const char* reason = nullptr;
    for (int k = 0; k < tries; ++k) {
        const Point step = steps[k];
        const Point predicted{last.x + step.x, last.y + step.y};
        if (k == 0) result_.predicted = predicted;
        // The previous contour moved by the step is where the target should be now.
        for (int i = 0; i < last_count_; ++i)
            last_points_[i] = {last_points_[i].x + step.x - applied.x, last_points_[i].y + step.y - applied.y};
        applied = step;
        prior_.set_polygon(last_points_.data(), last_count_, last_open_.data());
        // A grey source's layers (only where the scene is) are read where this try puts the target:
        // the view can turn a few pixels a frame either way in a fast closed loop, which the
        // smoothed velocity does not follow, and a map read off the target cuts into it.
        if (!chroma_->present) look_with_likelihood(step);
        rays_.extract(smoothed_, predicted, prior_, true, model_, clock_, deadline, contour_);
        reason = check_contour(predicted, confident);
        // The jumps may have let part of the contour out onto clutter: the smooth contour instead.
        if (reason && rays_.solve_without_jumps(prior_, contour_)) reason = check_contour(predicted, confident);
        if (!reason) break;
    }
    if (reason && confident) {
        // The rim is not found (covered, or lost in clutter), but the target's looks are: the last
        // contour, moved to where the filter found it, stands for it until the rim shows again —
        // if what it encloses there is about as grey as the target (not background the filter
        // settled on while the target is gone).
        coast_to({match_.at.x - last.x - applied.x, match_.at.y - last.y - applied.y});
        if (looks_like_target()) {
            follow(last);
            learn_looks(kFilterRate, true, &match_.at);
            remember_contour();
            return;
        }
    }
    if (reason) {
        declare_lost(reason);
        return;
    }
    follow(last);
    likelihood_.learn_motion(smoothed_, contour_, {contour_.centroid.x - last.x, contour_.centroid.y - last.y},
                             view_motion_);
    if (match_.psr > 0.0) psr_tracked_ = psr_tracked_ == 0.0 ? match_.psr : psr_tracked_ + kPsrRate * (match_.psr - psr_tracked_);
    model_.learn(contour_, scratch_);
    likelihood_.learn_colours(contour_, kColourRate);
    learn_looks(kFilterRate, true);
    remember_contour();
}

void Tracker::coast_to(Point shift) {
    contour_.size = last_count_;
    contour_.ref = match_.at;
    for (int i = 0; i < last_count_; ++i) {
        ContourPoint& q = contour_.points[i];
        q = {};
        q.p = {last_points_[i].x + shift.x, last_points_[i].y + shift.y};
        q.no_edge = last_open_[i] != 0;
    }
    polygon_area_centroid(contour_.points.data(), contour_.size, contour_.area, contour_.centroid);
    // The grey inside, as the rays see it: on the outer two thirds from the centroid to the rim.
    const Point c = contour_.centroid;
    for (int i = 0; i < last_count_; ++i) {
        ContourPoint& q = contour_.points[i];
        const double dx = q.p.x - c.x, dy = q.p.y - c.y;
        q.inside_mean = (sample_bilinear(smoothed_, c.x + 0.4 * dx, c.y + 0.4 * dy) +
                         sample_bilinear(smoothed_, c.x + 0.6 * dx, c.y + 0.6 * dy) +
                         sample_bilinear(smoothed_, c.x + 0.8 * dx, c.y + 0.8 * dy)) / 3.0f;
    }
}

bool Tracker::looks_like_target() const {
    if (!model_.valid) return true;
    float sum = 0.0f;
    for (float v : model_.inside_mean) sum += v;
    const double learned = sum / static_cast<float>(TargetModel::kBins);
    return std::abs(mean_inside_grey(contour_) - learned) <= TargetModel::kGreyTolerance * std::max<double>(model_.frame_mean, 1.0);
}

double Tracker::reacquire_bound() const { return std::max(tracked_area_, whole_area_.area()) / kReacquireAreaRatio; }

double Tracker::inside_grey_share() const { return mean_inside_grey(contour_) / std::max<double>(model_.frame_mean, 1.0); }

bool Tracker::look_again(TimePoint deadline) {
    if (!filter_.valid()) return false;
    const double last_radius = std::sqrt(std::max(tracked_area_, whole_area_.area()) / std::numbers::pi);
    // First where it was last seen ...
    const FilterMatch near = filter_.locate(smoothed_, *chroma_, last_seen_);
    result_.match_psr = near.psr;
    if (near.psr >= CorrelationFilter::kConfidentPsr && begin_track(near.at, last_radius, StartFrom::Filter, true, deadline)) return true;
    // ... then anywhere in the frame it can have reached, where a match must be about as clear as the
    // target's were.
    const FilterMatch found = sweep_.next(filter_, smoothed_, *chroma_);
    if (found.psr < std::max(CorrelationFilter::kConfidentPsr, kRedetectShare * psr_tracked_) || !within_reach(found.at, last_radius)) return false;
    const FilterMatch match = filter_.locate(smoothed_, *chroma_, found.at);  // centred on it: learned from there
    result_.match_psr = match.psr;
    return match.psr >= CorrelationFilter::kConfidentPsr && begin_track(match.at, last_radius, StartFrom::Filter, true, deadline);
}

bool Tracker::within_reach(Point p, double radius) const {
    const double reach = radius + tunables_.attention.max_jump_px * (untracked_frames_ + 1);
    return std::hypot(p.x - last_seen_.x, p.y - last_seen_.y) <= reach;
}

void Tracker::follow(Point last) {
    const Point moved{contour_.centroid.x - last.x, contour_.centroid.y - last.y};
    velocity_ = {velocity_.x + kVelocityRate * (moved.x - velocity_.x), velocity_.y + kVelocityRate * (moved.y - velocity_.y)};
}

const char* Tracker::check_contour(Point predicted, bool confident) {
    const char* reason = attention_.check(contour_, predicted, tunables_.attention);
    const double radius = std::sqrt(std::max(tracked_area_, 1.0) / std::numbers::pi);
    if (!reason && confident &&
        std::hypot(contour_.centroid.x - match_.at.x, contour_.centroid.y - match_.at.y) > kFilterAgreement * radius)
        reason = "the contour left the target the correlation filter finds";
    return reason;
}

void Tracker::declare_lost(const char* reason) {
    sweep_.restart();
    likelihood_.forget_motion();  // where the target was is no guide to where it is found again
    result_.state = TrackState::Lost;
    result_.has_contour = false;
    result_.lost_reason = reason;
    lost_frames_ = 0;
}

bool Tracker::watch_still_track(const GreyImage& frame) {
    if (!has_previous_) return true;
    const ViewShift& view = view_motion_.since_previous();
    if (!still_watch_.stands_still(contour_.centroid, view)) return true;
    const GreyImage& before = align_previous(previous_, frame, view.drift, aligned_previous_);
    result_.detection = detector_.detect(before, frame, tunables_.detect);
    return still_watch_.on_mover(result_.detection, contour_, detector_);
}

const FrameResult& Tracker::process(const GreyImage& frame, const Chroma& chroma, TimePoint deadline) {
    ++result_.frame;
    result_.lost_reason = nullptr;
    result_.off_target = false;
    result_.match_psr = 0.0;
    result_.detection = {};
    chroma_ = &chroma;
    likelihood_.begin_frame(frame, chroma, expected_view_);
    smoother_.smooth(frame, smoothed_);
    // A grey source's layers are read only in track(), where each try puts the target.
    if (chroma.present) look_with_likelihood();
    else rays_.use_likelihood(nullptr);
    // The frame's mean grey, in eight running sums: one sum is a chain of 16384 dependent adds.
    std::array<float, 8> sums{};
    for (int i = 0; i < kFramePixels; i += 8)
        for (int k = 0; k < 8; ++k) sums[k] += smoothed_.px[i + k];
    float sum = 0.0f;
    for (float s : sums) sum += s;
    model_.follow_exposure(sum / static_cast<float>(kFramePixels));
    // The caller says whether the camera was to hold still; the view's own motion says whether it
    // did (a recording, a camera shaken or on a vehicle). Frame differencing needs the view's shift
    // known, to align the two frames. The background is kept on the caller's word, and only for the
    // foreground term: with the term's weight at 0 it is not kept at all.
    view_motion_.take(smoothed_);
    const bool keep_background = detection_allowed_ && tunables_.rays.foreground_weight > 0.0;
    if (keep_background) background_.rate(smoothed_);
    else background_.reset();
    rays_.use_foreground(background_.foreground());

    if (result_.state == TrackState::Lost && ++lost_frames_ >= tunables_.attention.lost_frames)
        result_.state = TrackState::Detecting;

    const bool was_tracking = result_.state == TrackState::Tracking;
    if (was_tracking) {
        track(deadline);
        // A person's target that the filter still finds, and that is as grey as it was at the start,
        // is the target, standing still or not — unless the target as it looked at the start is
        // found where the motion is, surely and more clearly than where the track stands.
        if (result_.state == TrackState::Tracking && !watch_still_track(frame) &&
            !chosen_.vouches_for(smoothed_, chroma, contour_.centroid, result_.detection.centre, match_.psr,
                                 inside_grey_share())) {
            declare_lost("the track stood still while motion went on away from it");
            result_.off_target = true;
            filter_.reset();  // it learned the looks of something beside the mover: not to be looked for again
        }
    }
    // A target the contour check lost is looked for again by its looks in this very frame (with
    // attention.lost_frames at 0): still in view, they find it at once. Not a track dropped as off
    // the target (where it stood is no place to look), and no frame differencing until the next
    // frame (this frame's difference still shows where the target was).
    const bool just_lost = was_tracking && result_.state == TrackState::Lost && !result_.off_target &&
                           tunables_.attention.lost_frames == 0;
    if (just_lost) result_.state = TrackState::Detecting;
    if (result_.state == TrackState::Detecting) {
        bool found = false;
        still_watch_.restart();
        if (start_point_) {
            // Its whole size: the last contour may have been a sliver beside an occluder.
            const double last_radius = std::sqrt(std::max(tracked_area_, whole_area_.area()) / std::numbers::pi);
            // A re-acquisition tries the learned looks, then (just after the loss) afresh.
            auto reacquire = [&](Point m) {
                return begin_track(m, last_radius, StartFrom::Prediction, true, deadline) ||
                       (untracked_frames_ <= kFreshReacquireFrames && reacquire_afresh(m, last_radius, deadline));
            };
            found = reacquire_   ? reacquire(*start_point_)
                    : start_box_ ? begin_box_track(*start_box_, deadline)
                                 : begin_track(*start_point_, kStartRadiusPx, StartFrom::Person, false, deadline);
            // Something thin in front of the target's middle (a pole) hides the point itself: look
            // to either side of it, and above and below.
            for (int side = 0; !found && reacquire_ && side < 4; ++side) {
                const double d = kReacquireSideShift * last_radius;
                const Point offsets[] = {{-d, 0.0}, {d, 0.0}, {0.0, -d}, {0.0, d}};
                found = reacquire({start_point_->x + offsets[side].x, start_point_->y + offsets[side].y});
            }
            start_point_.reset();
            start_box_.reset();
        } else if (look_again(deadline)) {
            found = true;
        } else if (!just_lost && has_previous_ && detection_allowed_ && view_motion_.since_previous().known) {
            const GreyImage& before = align_previous(previous_, frame, view_motion_.since_previous().shift, aligned_previous_);
            result_.detection = detector_.detect(before, frame, tunables_.detect);
            const Detection& d = result_.detection;
            if (d.found) found = begin_detected(d, deadline);
        }
        result_.state = found ? TrackState::Tracking : TrackState::Detecting;
        result_.has_contour = found;
        result_.predicted = contour_.centroid;
    }
    if (!result_.has_contour) result_.match_psr = 0.0;
    untracked_frames_ = result_.has_contour ? 0 : untracked_frames_ + 1;
    if (keep_background) background_.learn(smoothed_, result_.has_contour ? &contour_ : nullptr);
    external_prediction_.reset();
    previous_ = frame;
    likelihood_.keep_frame(smoothed_);
    expected_view_.reset();
    has_previous_ = true;
    return result_;
}

}  // namespace rays
