// SPDX-License-Identifier: Apache-2.0
// Dynamic programming over the closed ring of rays (§2.4): one state per ray, minimising
//   E = Σ_i U_i(s_i) + Σ_i a_i (λ_{i+1} − λ_i)² + Σ_i b_i (λ'_{i} − λ'_{i−1})²,
// the discrete eq. 10 with eq. 9's first (α) and second (β) order terms, λ' = Δλ / Δφ.
// Optionally each of those smoothness terms is truncated at a jump cost κ where every state it joins
// is an edge: eq. 9 charges a step in λ without bound, so a thin protrusion (a leg, a head on a neck)
// costs more at its two flanks than its rays can gain, however clear their edges are. Truncated, a
// step between edges costs at most κ (a robust prior, as in Blake & Zisserman's weak string); steps
// to or from a "no edge" state keep their full cost, so a stretch without edges still follows its
// neighbours. κ = ∞ is eq. 9 exactly.
//
// The ring is closed, never cut open for good. Small rings are solved exactly by enumeration.
// Larger ones in three passes: (1) the open chain 0…M−1 with the unary and α terms only, solved
// exactly in O(M·S²): it only has to find a good place to cut; (2) the ring cut at the link where
// pass 1's contour is smoothest, the two rays there fixed to pass 1's states, solved exactly in
// O(M·S³) with every term including the wrap-around; (3) the same from pass 2's states, cut opposite
// that cut, when pass 2 changed any state. Each closed pass contains the previous answer, so the
// energy never rises. The result is a consistent closed contour; its distance from the true optimum
// is bounded by tests/core/test_ring_dp.cpp against brute force, with and without the jump cost.
#pragma once
#include <array>
#include <limits>
#include <vector>

#include "core/lanes.hpp"

namespace rays {

class RingDp {
public:
    RingDp(int max_nodes, int max_states);

    void reset(int nodes);
    // lam and unary hold `states` values; gap is the angle (rad) to the next node round the ring.
    // The first `capped` states are edges: a smoothness term between edge states only is truncated
    // at the jump cost; any term that involves another state is not.
    void set_node(int i, int states, const float* lam, const float* unary, float gap_to_next, int capped = 0);

    // κ: the most one smoothness term between edge states may charge (κ ≤ 0: never truncated).
    void set_jump_cost(double kappa);

    // Minimises E for the given α', β' (already divided by the contour scale²). Writes one state per
    // node and returns the energy of that choice.
    double solve(double alpha, double beta, int* states);

    // E of a given choice of states (also what the tests' brute force minimises).
    double energy(double alpha, double beta, const int* states) const;

private:
    // Exact DP over the ring starting at node `first`, the states of the first two nodes fixed to
    // (a, b), every term included (the wrap-around back to them too). O(M·S³).
    double closed_chain(double alpha, double beta, int first, int a, int b, int* states);
    // Exact DP over the open chain 0…M−1 with the unary and α terms only; writes its states. O(M·S²).
    void open_first_order(double alpha, int* states);
    double enumerate(double alpha, double beta, int* states);
    // The link i → i+1 (from ≤ i < to, taken round the ring) with the least α term under the states.
    int smoothest_link(double alpha, const int* states, int from, int to) const;
    float lam(int node, int s) const { return lam_[node * stride_ + s]; }
    float unary(int node, int s) const { return unary_[node * stride_ + s]; }
    // The most a smoothness term may charge as far as state s of `node` is concerned.
    // A table, not a branch: which states are edges is as good as random to a branch predictor.
    float cap(int node, int s) const { return caps_[s < capped_[node]]; }
    // The same for the states of lane group `group` (states kLanes·group … kLanes·group + kLanes − 1).
    Lanes cap_lanes(int node, int group) const {
        return group * kLanes + kLaneOffsets < capped_[node] ? caps_[1] : caps_[0];
    }

    int max_nodes_;
    int stride_;  // room for a node's states: the most it may have, in whole groups of vector lanes
    int nodes_ = 0;
    std::vector<float> lam_, unary_, gap_;
    std::vector<int> states_, capped_;
    std::array<float, 2> caps_;  // what a term may charge: [0] a state that is not an edge (∞), [1] an edge (κ)
    std::vector<float> value_, next_value_;  // V(s_{i−1}, s_i), S² per step
    std::vector<unsigned char> back_;       // argmin s_{i−2} for each node and pair, M·S²
    std::vector<Lanes> prev_lam_, prev_cap_;  // the closed chain's previous node: λ and caps in every lane
    std::vector<Lanes> next_cap_;             // its next node's caps, by lane groups
    std::vector<int> scratch_;
};

}  // namespace rays
