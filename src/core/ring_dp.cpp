// SPDX-License-Identifier: Apache-2.0
#include "core/ring_dp.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

#include "common/frame_kernel.hpp"
#include "core/lanes.hpp"

namespace rays {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr long kEnumerateLimit = 4096;  // rings with fewer joint states are solved by enumeration
// The chains' innermost loops run over a node's states in vector lanes (lanes.hpp); four lanes
// hold the usual K = 3 edges and "no edge". Back pointers are bytes (a node has at most 256 states;
// the configuration allows 33), a lane group's stored at once.
using LaneBytes = unsigned char __attribute__((vector_size(kLanes)));

}  // namespace

RingDp::RingDp(int max_nodes, int max_states)
    : max_nodes_(max_nodes),
      stride_(whole_lanes(max_states)),
      lam_(static_cast<std::size_t>(max_nodes) * stride_),
      unary_(lam_.size()),
      gap_(max_nodes),
      states_(max_nodes),
      capped_(max_nodes),
      caps_{kInf, kInf},
      value_(static_cast<std::size_t>(stride_) * stride_),
      next_value_(value_.size()),
      back_(static_cast<std::size_t>(max_nodes) * stride_ * stride_),
      prev_lam_(stride_),
      prev_cap_(stride_),
      next_cap_(stride_ / kLanes),
      scratch_(max_nodes) {}

void RingDp::set_jump_cost(double kappa) { caps_[1] = kappa > 0 ? static_cast<float>(kappa) : kInf; }

void RingDp::reset(int nodes) { nodes_ = std::clamp(nodes, 0, max_nodes_); }

void RingDp::set_node(int i, int states, const float* lam, const float* unary, float gap_to_next, int capped) {
    states_[i] = states;
    capped_[i] = capped;
    for (int s = 0; s < states; ++s) {
        lam_[i * stride_ + s] = lam[s];
        unary_[i * stride_ + s] = unary[s];
    }
    gap_[i] = gap_to_next;
}

double RingDp::energy(double alpha, double beta, const int* states) const {
    const int m = nodes_;
    double e = 0.0;
    for (int i = 0; i < m; ++i) {
        const int prev = (i + m - 1) % m, next = (i + 1) % m;
        const double l0 = lam(prev, states[prev]), l1 = lam(i, states[i]), l2 = lam(next, states[next]);
        e += unary(i, states[i]);
        const double d = (l2 - l1) / gap_[i] - (l1 - l0) / gap_[prev];
        const double ca = std::max(cap(i, states[i]), cap(next, states[next]));
        const double cb = std::max<double>(ca, cap(prev, states[prev]));
        e += std::min<double>(alpha / gap_[i] * (l2 - l1) * (l2 - l1), ca);    // eq. 9, α|λ'|², truncated
        e += std::min<double>(beta / (0.5 * (gap_[prev] + gap_[i])) * d * d, cb);  // eq. 9, β|λ''|², truncated
    }
    return e;
}

double RingDp::enumerate(double alpha, double beta, int* states) {
    const int m = nodes_;
    std::fill(scratch_.begin(), scratch_.begin() + m, 0);
    double best = std::numeric_limits<double>::infinity();
    for (;;) {
        const double e = energy(alpha, beta, scratch_.data());
        if (e < best) {
            best = e;
            std::copy(scratch_.begin(), scratch_.begin() + m, states);
        }
        int i = 0;
        while (i < m && ++scratch_[i] == states_[i]) scratch_[i++] = 0;
        if (i == m) return best;
    }
}

RAYS_FRAME_KERNEL
double RingDp::closed_chain(double alpha, double beta, int first, int a, int b, int* states) {
    const int m = nodes_, stride = stride_;
    auto node = [&](int t) { return first + t < m ? first + t : first + t - m; };  // 0 ≤ t < m
    auto pair_cost = [&](int i, int si, int sj) {  // eq. 9, α term between node i and the next
        const int j = (i + 1) % m;
        const float d = lam(j, sj) - lam(i, si);
        return std::min(static_cast<float>(alpha) / gap_[i] * d * d, std::max(cap(i, si), cap(j, sj)));
    };
    // V(s0, s1) for the first link.
    const int n0 = node(0), n1 = node(1);
    for (int p = 0; p < states_[n0]; ++p)
        for (int q = 0; q < states_[n1]; ++q)
            value_[p * stride + q] = (p != a || q != b)
                                         ? kInf
                                         : unary(n0, p) + unary(n1, q) + pair_cost(n0, p, q);
    for (int t = 1; t + 1 < m; ++t) {
        const int prev = node(t - 1), cur = node(t), next = node(t + 1);
        const float gp = gap_[prev], gc = gap_[cur];
        const float bw = static_cast<float>(beta) / (0.5f * (gp + gc));
        const float inv_gp = 1.0f / gp, inv_gc = 1.0f / gc, aw = static_cast<float>(alpha) * inv_gc;
        const int np = states_[prev], nr = states_[next];
        const int chunks = (nr + kLanes - 1) / kLanes;  // the next node's states, kLanes at a time
        // Its λ and unary costs by whole lane groups (lanes past its states carry what they carry:
        // their results are never read).
        const float* lam_next = &lam_[static_cast<std::size_t>(next) * stride];
        const float* unary_next = &unary_[static_cast<std::size_t>(next) * stride];
        unsigned char* back = &back_[static_cast<std::size_t>(t + 1) * stride * stride];
        // The previous node's λ and caps, each in every lane, and the next node's caps by lane
        // groups, once for all their uses below.
        for (int p = 0; p < np; ++p) {
            prev_lam_[p] = lam(prev, p) + Lanes{};
            prev_cap_[p] = cap(prev, p) + Lanes{};
        }
        for (int k = 0; k < chunks; ++k) next_cap_[k] = cap_lanes(next, k);
        for (int q = 0; q < states_[cur]; ++q) {
            const float lq = lam(cur, q);
            const float cq = cap(cur, q);
            const Lanes lq_lanes = lq + Lanes{};
            // Every state r of the next node at once, in vector lanes: the best previous state p for
            // (q, r), the first p on a tie.
            for (int k = 0; k < chunks; ++k) {
                const Lanes lam_r = load_lanes(lam_next + k * kLanes);
                const Lanes cap_r = next_cap_[k];
                const Lanes slope_out = (lam_r - lq) * inv_gc;
                const Lanes cap_qr = cap_r > cq ? cap_r : cq;
                Lanes best = kInf + Lanes{};
                LaneIndex arg{}, p_lanes{};
                for (int p = 0; p < np; ++p, p_lanes += 1) {
                    const Lanes slope_in = (lq_lanes - prev_lam_[p]) * inv_gp;
                    const Lanes d = slope_out - slope_in;
                    const Lanes bound = cap_qr > prev_cap_[p] ? cap_qr : prev_cap_[p];
                    const Lanes beta_term = bw * d * d;
                    const Lanes v = value_[p * stride + q] + (bound < beta_term ? bound : beta_term);  // eq. 9, β term
                    const LaneIndex better = v < best;
                    best = better ? v : best;
                    arg = better ? p_lanes : arg;
                }
                const Lanes step = lam_r - lq;
                const Lanes alpha_term = aw * step * step;
                const Lanes through = best + (cap_qr < alpha_term ? cap_qr : alpha_term);  // eq. 9, α term
                store_lanes(&next_value_[q * stride + k * kLanes], through + load_lanes(unary_next + k * kLanes));
                const auto arg_bytes = __builtin_convertvector(arg, LaneBytes);
                std::memcpy(&back[q * stride + k * kLanes], &arg_bytes, sizeof arg_bytes);
            }
        }
        std::swap(value_, next_value_);
    }
    // Close: the last pair (p, q) at positions m−2, m−1.
    const int nl = node(m - 2), nq = node(m - 1);
    float best = kInf;
    int bp = 0, bq = 0;
    for (int p = 0; p < states_[nl]; ++p)
        for (int q = 0; q < states_[nq]; ++q) {
            const float l0 = lam(nl, p), l1 = lam(nq, q), la = lam(n0, a), lb = lam(n1, b);
            const float d1 = (la - l1) / gap_[nq] - (l1 - l0) / gap_[nl];
            const float d2 = (lb - la) / gap_[n0] - (la - l1) / gap_[nq];
            const float c1 = std::max({cap(nl, p), cap(nq, q), cap(n0, a)});
            const float c2 = std::max({cap(nq, q), cap(n0, a), cap(n1, b)});
            const float v = value_[p * stride + q] +
                            std::min(static_cast<float>(beta) / (0.5f * (gap_[nl] + gap_[nq])) * d1 * d1, c1) +
                            pair_cost(nq, q, a) +
                            std::min(static_cast<float>(beta) / (0.5f * (gap_[nq] + gap_[n0])) * d2 * d2, c2);
            if (v < best) {
                best = v;
                bp = p;
                bq = q;
            }
        }
    states[nq] = bq;
    states[nl] = bp;
    for (int t = m - 1; t >= 2; --t) {
        const unsigned char* back = &back_[static_cast<std::size_t>(t) * stride * stride];
        states[node(t - 2)] = back[states[node(t - 1)] * stride + states[node(t)]];
    }
    return best;
}

RAYS_FRAME_KERNEL
void RingDp::open_first_order(double alpha, int* states) {
    const int m = nodes_, stride = stride_;
    float* value = value_.data();  // V(s_t) for the chain so far
    float* next = next_value_.data();
    for (int s = 0; s < states_[0]; ++s) value[s] = unary(0, s);
    for (int t = 1; t < m; ++t) {
        const float a = static_cast<float>(alpha) / gap_[t - 1];
        const int nq = states_[t];
        unsigned char* back = &back_[static_cast<std::size_t>(t) * stride];
        // This node's states in vector lanes, as in the closed chain (lanes past its states carry
        // what they carry: never read): the best previous state p for each, the first p on a tie.
        for (int k = 0; k * kLanes < nq; ++k) {
            const Lanes lq = load_lanes(&lam_[static_cast<std::size_t>(t) * stride + k * kLanes]);
            const Lanes cq = cap_lanes(t, k);
            Lanes best = kInf + Lanes{};
            LaneIndex arg = LaneIndex{};
            for (int p = 0; p < states_[t - 1]; ++p) {
                const Lanes d = lq - lam(t - 1, p);
                const float cap_p = cap(t - 1, p);
                const Lanes bound = cq > cap_p ? cq : cap_p;
                const Lanes alpha_term = a * d * d;
                const Lanes v = value[p] + (bound < alpha_term ? bound : alpha_term);  // eq. 9, α term
                const LaneIndex better = v < best;
                best = better ? v : best;
                arg = better ? p : arg;
            }
            store_lanes(next + k * kLanes, best + load_lanes(&unary_[static_cast<std::size_t>(t) * stride + k * kLanes]));
            const auto arg_bytes = __builtin_convertvector(arg, LaneBytes);
            std::memcpy(back + k * kLanes, &arg_bytes, sizeof arg_bytes);
        }
        std::swap(value, next);
    }
    states[m - 1] = static_cast<int>(std::min_element(value, value + states_[m - 1]) - value);
    for (int t = m - 1; t >= 1; --t) states[t - 1] = back_[static_cast<std::size_t>(t) * stride + states[t]];
}

int RingDp::smoothest_link(double alpha, const int* states, int from, int to) const {
    int best = from;
    double smoothest = std::numeric_limits<double>::infinity();
    for (int k = from; k < to; ++k) {
        const int i = k % nodes_, j = (k + 1) % nodes_;
        const double d = lam(j, states[j]) - lam(i, states[i]);
        const double link = std::min<double>(alpha / gap_[i] * d * d, std::max(cap(i, states[i]), cap(j, states[j])));
        if (link < smoothest) {
            smoothest = link;
            best = i;
        }
    }
    return best % nodes_;
}

double RingDp::solve(double alpha, double beta, int* states) {
    const int m = nodes_;
    if (m == 0) return 0.0;
    long joint = 1;
    for (int i = 0; i < m && joint <= kEnumerateLimit; ++i) joint *= states_[i];
    if (m < 4 || joint <= kEnumerateLimit) return enumerate(alpha, beta, states);
    open_first_order(alpha, states);  // pass 1
    // Pass 2 closes the ring, cut at the smoothest link of pass 1's contour, so the fixed pair is not
    // a jump; when that changed the contour, pass 3 closes it again from pass 2's contour, cut
    // opposite. Each pass contains the previous answer: the energy never rises.
    const int cut = smoothest_link(alpha, states, 0, m - 1);
    std::copy(states, states + m, scratch_.begin());
    closed_chain(alpha, beta, cut, states[cut], states[(cut + 1) % m], states);
    if (!std::equal(states, states + m, scratch_.begin())) {  // closing moved the contour: once more
        const int other = (cut + m / 2) % m;
        closed_chain(alpha, beta, other, states[other], states[(other + 1) % m], states);
    }
    return energy(alpha, beta, states);
}

}  // namespace rays
