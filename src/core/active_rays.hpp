// SPDX-License-Identifier: Apache-2.0
// Contour extraction with active rays (§2.2–2.4) and its any-time refinement (§2.3, Fig. 6).
#pragma once
#include <vector>

#include "core/clock.hpp"
#include "core/contour.hpp"
#include "core/polar_prior.hpp"
#include "core/ray_hypotheses.hpp"
#include "core/ray_table.hpp"
#include "core/ring_dp.hpp"
#include "core/target_model.hpp"

namespace rays {

class ActiveRays {
public:
    explicit ActiveRays(const TrackerCapacity& capacity);

    // Applies tunables within the capacities; false (and nothing changed) when they do not fit.
    bool configure(const RaysTunables& tunables);
    const RayTable& table() const { return table_; }
    // The still camera's foreground (BackgroundModel) for the extractions that follow; null: none.
    void use_foreground(const FloatImage* foreground) { foreground_ = foreground; }
    // The target's colour likelihood (AppearanceModel) for the extractions that follow; null: none.
    void use_likelihood(const LikelihoodMap* likelihood) { likelihood_ = likelihood; }

    // Extracts the contour round m on the smoothed image. `prior` says where the contour is expected
    // (the previous frame's contour, or a circle); `use_temporal` enables the pull toward it; `model`
    // carries the learned polarity, appearance and rim contrast (ignored while !model.valid).
    // Refinement stops before `deadline` (read through `clock`); the coarse contour of the first
    // centroid iteration is always computed. `max_level` ≥ 0 stops refinement after that level
    // (for measuring the any-time curve). `m_moves` false holds m where it is (no eq. 11 iterations:
    // the contour is the one seen from m, which it encloses). No allocation.
    void extract(const FloatImage& image, Point m, PolarPrior& prior, bool use_temporal, const TargetModel& model,
                 const Clock& clock, TimePoint deadline, Contour& out, int max_level = -1, bool m_moves = true);
    // The last extraction's final contour again, with eq. 9 whole: a tracking contour's smoothness is
    // truncated at rays.jump_cost, which may let part of it out onto clutter. The same rays and
    // hypotheses: only the ring DP runs again (what a second extraction without the truncation would
    // find, at a fraction of its time). `prior` is the one the extraction used. False, and `out`
    // untouched, when that contour was found without the truncation.
    bool solve_without_jumps(const PolarPrior& prior, Contour& out);

private:
    void shoot(int ray, const FloatImage& image, Point m, const PolarPrior& prior, bool use_temporal,
               const TargetModel& model);
    // (v) of shoot(): a rim that gives up `nats` of the colour split's likelihood (Hypothesis::appearance).
    float appearance_cost(float nats) const;
    void solve(float radius, const PolarPrior& prior);
    void write_contour(Point m, Contour& out) const;
    int previous_active(int ray) const;
    int next_active(int ray) const;

    TrackerCapacity capacity_;
    RaysTunables t_;
    RayTable table_;
    RayProfiler profiler_;
    RingDp dp_;
    int state_stride_;                    // max_hypotheses + 1: the "no edge" state is last
    bool jumps_ = false;                  // the ring DP truncates its smoothness at the jump cost
    Point last_m_;                        // the last extraction's final reference point
    const FloatImage* foreground_ = nullptr;  // see use_foreground()
    const LikelihoodMap* likelihood_ = nullptr;  // see use_likelihood()
    float rim_contrast_ = 0;              // normaliser of eq. 7 for this extraction

    std::vector<unsigned char> active_;   // per ray: shot at the current reference point
    std::vector<int> hyp_count_;
    std::vector<Hypothesis> hyp_;         // per ray × max_hypotheses
    std::vector<float> cost_;             // per ray × states: external energy, per radian
    std::vector<float> state_lambda_;     // per ray × states
    std::vector<float> lambda_end_;       // per ray: last λ inside the image
    std::vector<int> chosen_;             // per ray: state picked by the DP
    std::vector<float> lambda_out_;       // per ray: contour λ (no-edge rays interpolated)
    std::vector<int> node_ray_, node_state_, pending_;
    std::vector<float> pending_gap_, unary_;
};

}  // namespace rays
