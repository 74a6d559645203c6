// SPDX-License-Identifier: Apache-2.0
#include "core/active_rays.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr float kTwoPi = 2.0f * std::numbers::pi_v<float>;
constexpr float kDefaultContrast = 12.0f;  // grey/px: eq. 7's normaliser before a rim has been learned
constexpr float kEdgeCap = 2.0f;           // an edge this many times the rim contrast² gains no more
constexpr float kSpreadFloor = 6.0f;       // grey: the least spread the region term assumes
constexpr float kContrastShare = 0.25f;    // of |outside − inside|: how far the inside may stray from the target's grey
constexpr float kUnseenRegion = 1.0f;      // region term of an edge whose inside the ray could not see (of 0…5)
constexpr float kAppearanceCap = 4.0f;     // the colour term gains no more than this many clear samples
constexpr float kCrossingTolerance = 0.15f;
constexpr int kCheckEvery = 8;             // rays between deadline checks
constexpr float kMinRadiusPx = 8.0f;       // least contour scale for the smoothness and temporal terms
constexpr float kSearchScale = 1.6f;       // while tracking, search λ up to this × λ_prior …
constexpr float kSearchMarginPx = 10.0f;   // … plus this

float clamp_coord(double v) { return static_cast<float>(std::clamp(v, 1.0, kFrameSize - 2.0)); }

}  // namespace

ActiveRays::ActiveRays(const TrackerCapacity& capacity)
    : capacity_(capacity),
      table_(capacity.max_rays),
      profiler_(capacity),
      dp_(capacity.max_rays, capacity.max_hypotheses + 1),
      state_stride_(capacity.max_hypotheses + 1),
      active_(capacity.max_rays),
      hyp_count_(capacity.max_rays),
      hyp_(static_cast<std::size_t>(capacity.max_rays) * capacity.max_hypotheses),
      cost_(static_cast<std::size_t>(capacity.max_rays) * state_stride_),
      state_lambda_(cost_.size()),
      lambda_end_(capacity.max_rays),
      chosen_(capacity.max_rays),
      lambda_out_(capacity.max_rays),
      node_ray_(capacity.max_rays),
      node_state_(capacity.max_rays),
      pending_(capacity.max_rays),
      pending_gap_(capacity.max_rays),
      unary_(state_stride_) {
    configure(t_);
}

bool ActiveRays::configure(const RaysTunables& tunables) {
    if (tunables.count < 2 || tunables.count > capacity_.max_rays) return false;
    if (tunables.hypotheses < 1 || tunables.hypotheses > capacity_.max_hypotheses) return false;
    if (!profiler_.configure(tunables)) return false;
    t_ = tunables;
    table_.set_count(t_.count);
    return true;
}

int ActiveRays::previous_active(int ray) const {
    const int n = table_.count();
    for (int k = 1, r = ray; k < n; ++k) {
        r = r > 0 ? r - 1 : n - 1;  // round the ring without a division
        if (active_[r]) return r;
    }
    return ray;
}

int ActiveRays::next_active(int ray) const {
    const int n = table_.count();
    for (int k = 1, r = ray; k < n; ++k) {
        r = r + 1 < n ? r + 1 : 0;
        if (active_[r]) return r;
    }
    return ray;
}

float ActiveRays::appearance_cost(float nats) const {
    return static_cast<float>(t_.appearance_weight) * std::min(nats / LikelihoodMap::kMaxLogOdds, kAppearanceCap);
}

RAYS_FRAME_KERNEL
void ActiveRays::shoot(int ray, const FloatImage& image, Point m, const PolarPrior& prior, bool use_temporal,
                       const TargetModel& model) {
    Hypothesis* hyp = &hyp_[static_cast<std::size_t>(ray) * capacity_.max_hypotheses];
    float end = 0;
    // While tracking, the search reaches only as far beyond the expected contour as it can move;
    // where the previous contour found no edge, the contour may be anywhere along the ray (a limb
    // coming back into view), so the whole ray is searched. A box start's rays search within its box.
    const float limit = std::min(use_temporal && !prior.open(ray) ? kSearchScale * prior.lambda(ray) + kSearchMarginPx
                                                                  : static_cast<float>(t_.lambda_max_px),
                                 prior.search_to(ray));
    const int n = profiler_.shoot(image, foreground_, likelihood_, m, table_.cos_at(ray), table_.sin_at(ray), prior.search_from(ray),
                                  limit, hyp, end);
    hyp_count_[ray] = n;
    lambda_end_[ray] = end;
    active_[ray] = 1;

    float* cost = &cost_[static_cast<std::size_t>(ray) * state_stride_];
    float* lam = &state_lambda_[static_cast<std::size_t>(ray) * state_stride_];
    const float lp = std::min(prior.lambda(ray), std::max(end, static_cast<float>(t_.lambda_min_px)));
    const float radius = std::max(kMinRadiusPx, prior.mean_radius());
    const int bin = TargetModel::bin(static_cast<float>(table_.angle(ray)));
    for (int h = 0; h < n; ++h) {
        const Hypothesis& e = hyp[h];
        // eq. 7 / 17: −|∂ρ/∂λ|², in units of the rim's own contrast and saturating, so a far
        // stronger background edge cannot outbid everything else.
        const float g = e.grad / rim_contrast_;
        float c = -std::min(g * g, kEdgeCap);
        if (model.valid) {
            // (i) polarity: an edge of the sign opposite to the learned rim costs more.
            const float pol = model.polarity[bin];
            if (e.grad * pol < 0) c += static_cast<float>(t_.polarity_weight) * std::abs(pol);
            // (ii) 1-D region term: inside like the target, the band outside unlike it. Where the ray
            // saw little of the inside clear of the rim, the term tends to a middling value.
            const float mu = model.inside_mean[bin];
            // The tolerance grows with the contrast between the target and its background there: a thin
            // part (a leg), blurred toward the background, still looks more like the target than not.
            const float ob = model.outside_mean[bin];
            const float tau = std::max(model.inside_spread + kSpreadFloor,
                                       ob >= 0 ? kContrastShare * std::abs(ob - mu) : 0.0f);
            const float dev2 = std::max(0.0f, e.inside_msq - 2.0f * mu * e.inside_mean + mu * mu);
            float region = std::min(dev2 / (tau * tau), 4.0f);
            if (e.outside_mean >= 0) region += std::max(0.0f, 1.0f - std::abs(e.outside_mean - mu) / (2.0f * tau));
            const float seen = inside_reliability(e.lambda);
            c += static_cast<float>(t_.region_weight) * (seen * region + (1.0f - seen) * kUnseenRegion);
        }
        // (iv) where the still camera's background is known: an edge where the ray leaves the
        // foreground costs less, one where it enters the foreground more.
        c -= static_cast<float>(t_.foreground_weight) * e.foreground_step;
        // (v) with the target's colours learned: a rim away from where the ray's colours split into
        // target and background costs the log-likelihood it gives up, in units of one clear sample.
        c += appearance_cost(e.appearance);
        if (use_temporal) {
            // (iii) temporal coupling toward the previous contour, bounded so a real change can win.
            const float d = (e.lambda - lp) / (0.2f * radius + 2.0f);
            c += static_cast<float>(t_.temporal_weight) * std::min(d * d, 4.0f);
        }
        cost[h] = c;
        lam[h] = e.lambda;
    }
    // "No edge on this ray": held at the expected λ, which the target's colours may also speak against.
    cost[n] = static_cast<float>(t_.none_cost) + appearance_cost(profiler_.appearance_at(lp));
    lam[n] = lp;
    // Until the DP has seen this ray, its cheapest state stands for it (orders the next level's rays).
    lambda_out_[ray] = lam[std::min_element(cost, cost + n + 1) - cost];
}

void ActiveRays::solve(float radius, const PolarPrior& prior) {
    const int n = table_.count();
    int nodes = 0;
    for (int r = 0; r < n; ++r)
        if (active_[r]) node_ray_[nodes++] = r;
    // A tracking extraction's final contour: a step in λ between edges costs at most κ (ring_dp.hpp).
    // A new target's first contour and the coarse contours m converges on keep eq. 9 whole.
    dp_.set_jump_cost(jumps_ ? t_.jump_cost : 0.0);
    dp_.reset(nodes);
    auto gap_after = [&](int j) {
        const int a = node_ray_[j], b = node_ray_[(j + 1) % nodes];
        float g = static_cast<float>(table_.angle(b) - table_.angle(a));
        return g <= 0 ? g + kTwoPi : g;
    };
    float gap_before = gap_after(nodes - 1);
    for (int j = 0; j < nodes; ++j) {
        const int r = node_ray_[j];
        const float gap = gap_after(j);
        const float weight = 0.5f * (gap_before + gap);  // eq. 10: the ray stands for this much angle
        const int states = hyp_count_[r] + 1;
        const float* cost = &cost_[static_cast<std::size_t>(r) * state_stride_];
        for (int s = 0; s < states; ++s) unary_[s] = cost[s] * weight;
        dp_.set_node(j, states, &state_lambda_[static_cast<std::size_t>(r) * state_stride_], unary_.data(), gap, hyp_count_[r]);
        gap_before = gap;
    }
    const double scale = std::max(kMinRadiusPx, radius);  // λ measured in contour radii
    const double scale2 = scale * scale;
    dp_.solve(t_.alpha / scale2, t_.beta / scale2, node_state_.data());
    for (int j = 0; j < nodes; ++j) chosen_[node_ray_[j]] = node_state_[j];
    // node_state_ is reused below as scratch: the previous node with an edge.

    // A "no edge" ray takes λ interpolated (in angle) from its nearest neighbours with an edge:
    // one sweep each way round the ring finds them.
    auto has_edge = [&](int j) { const int r = node_ray_[j]; return chosen_[r] < hyp_count_[r]; };
    auto lambda_of = [&](int j) {
        const int r = node_ray_[j];
        return state_lambda_[static_cast<std::size_t>(r) * state_stride_ + chosen_[r]];
    };
    int last = -1;
    for (int k = 0; k < 2 * nodes; ++k)  // previous node with an edge, for every node
        if (has_edge(k % nodes)) last = k % nodes; else if (k >= nodes) node_state_[k % nodes] = last;
    last = -1;
    for (int k = 0; k < 2 * nodes; ++k) {  // next node with an edge, walking backwards
        const int j = (2 * nodes - 1 - k) % nodes;
        if (has_edge(j)) { last = j; continue; }
        if (k < nodes) continue;
        const int r = node_ray_[j];
        const int jp = node_state_[j], jn = last;
        if (jp < 0 || jn < 0) {
            lambda_out_[r] = prior.lambda(r);
            continue;
        }
        auto ccw = [&](int from, int to) {
            float d = static_cast<float>(table_.angle(node_ray_[to]) - table_.angle(node_ray_[from]));
            return d <= 0 ? d + kTwoPi : d;
        };
        const float span = ccw(jp, jn), along = ccw(jp, j);
        const float lp = lambda_of(jp), ln = lambda_of(jn);
        lambda_out_[r] = std::min(lp + (ln - lp) * (span > 0 ? along / span : 0.5f), std::max(lambda_end_[r], 1.0f));
    }
    for (int j = 0; j < nodes; ++j)
        if (has_edge(j)) lambda_out_[node_ray_[j]] = lambda_of(j);
}

RAYS_FRAME_KERNEL
void ActiveRays::write_contour(Point m, Contour& out) const {
    const int n = table_.count();
    int size = 0, none = 0;
    for (int r = 0; r < n; ++r) {
        if (!active_[r]) continue;
        ContourPoint& c = out.points[size];
        const float lam = lambda_out_[r];
        c.phi = static_cast<float>(table_.angle(r));
        c.lambda = lam;
        c.p = {m.x + lam * table_.cos_at(r), m.y + lam * table_.sin_at(r)};  // eq. 8
        const int s = chosen_[r];
        c.no_edge = s >= hyp_count_[r];
        out.crossing_count[size] = 0;
        if (c.no_edge) {
            ++none;
            c.grad = c.inside_mean = c.inside_sd = 0;
            c.outside_mean = -1;
        } else {
            const Hypothesis& h = hyp_[static_cast<std::size_t>(r) * capacity_.max_hypotheses + s];
            c.grad = h.grad;
            c.inside_mean = h.inside_mean;
            c.inside_sd = std::sqrt(std::max(0.0f, h.inside_msq - h.inside_mean * h.inside_mean));
            c.outside_mean = h.outside_mean;
        }
        // Further crossings (§2.4): strong hypotheses that continue on both neighbouring rays
        // (the matching of eq. 14), e.g. where a ray passes through a concave notch.
        const int prev = previous_active(r), next = next_active(r);
        for (int h = 0; h < hyp_count_[r] && out.crossing_count[size] < out.max_crossings; ++h) {
            if (h == s) continue;
            const Hypothesis& e = hyp_[static_cast<std::size_t>(r) * capacity_.max_hypotheses + h];
            if (std::abs(e.grad) < 0.5f * rim_contrast_) continue;
            const float tol = std::max(2.0f, kCrossingTolerance * e.lambda);
            auto continues = [&](int rr) {
                for (int k = 0; k < hyp_count_[rr]; ++k)
                    if (std::abs(hyp_[static_cast<std::size_t>(rr) * capacity_.max_hypotheses + k].lambda - e.lambda) <= tol)
                        return true;
                return false;
            };
            if (continues(prev) && continues(next))
                out.crossings[static_cast<std::size_t>(size) * out.max_crossings + out.crossing_count[size]++] = e.lambda;
        }
        ++size;
    }
    out.size = size;
    out.no_edge_rays = none;
    out.ref = m;
    polygon_area_centroid(out.points.data(), size, out.area, out.centroid);
}

void ActiveRays::extract(const FloatImage& image, Point m0, PolarPrior& prior, bool use_temporal,
                         const TargetModel& model, const Clock& clock, TimePoint deadline, Contour& out,
                         int max_level, bool m_moves) {
    const int n = table_.count();
    jumps_ = false;  // m converges on eq. 9 whole: a coarse ray's jump would pull it off the target
    rim_contrast_ = model.valid ? std::max(model.rim_contrast, 2.0f * static_cast<float>(t_.edge_floor))
                                : kDefaultContrast;
    int centroid_level = 0;
    while (centroid_level + 1 < table_.levels() && table_.level_end(centroid_level) < std::min(t_.centroid_rays, n))
        ++centroid_level;
    const int coarse_rays = table_.level_end(centroid_level);

    Point m{clamp_coord(m0.x), clamp_coord(m0.y)};
    out.deadline_hit = false;
    out.iterations = 0;
    TimePoint t0 = clock.now();
    double ray_cost_ns = 0, node_cost_ns = 0;  // measured costs, for predicting what still fits
    const int iterations = m_moves ? t_.centroid_iterations : 1;
    for (int it = 0; it < iterations; ++it) {
        prior.resample(table_, m, t_.lambda_min_px, t_.lambda_max_px);
        std::fill(active_.begin(), active_.begin() + n, 0);
        const TimePoint a = clock.now();
        for (int k = 0; k < coarse_rays; ++k) shoot(table_.order(k), image, m, prior, use_temporal, model);
        const TimePoint b = clock.now();
        solve(prior.mean_radius(), prior);
        write_contour(m, out);
        const TimePoint c = clock.now();
        ray_cost_ns = std::chrono::duration<double, std::nano>(b - a).count() / coarse_rays;
        node_cost_ns = std::chrono::duration<double, std::nano>(c - b).count() / coarse_rays;
        ++out.iterations;
        // eq. 11: m moves to the contour's centre of gravity. We take the centre of the enclosed
        // area rather than eq. 11's angle-weighted mean of the boundary points: the latter drifts
        // toward the side where the contour is far from m, the area centre does not.
        const Point centre = out.centroid;
        const double moved = std::hypot(centre.x - m.x, centre.y - m.y);
        if (moved < t_.centroid_tol_px || it + 1 == iterations) break;
        const TimePoint now = clock.now();
        if (now + (now - t0) / (it + 1) > deadline) {
            out.deadline_hit = true;
            break;
        }
        m = {clamp_coord(centre.x), clamp_coord(centre.y)};
    }
    int levels = centroid_level + 1;
    const int final_level = max_level < 0 ? table_.levels() - 1 : std::min(max_level, table_.levels() - 1);

    // Any-time refinement (Fig. 6): each level halves Δφ; within a level, rays go first where
    // neighbouring contour points are furthest apart (§2.3), so a level cut short spends its rays
    // best. The DP over the ring runs once, on every ray shot, when refinement ends — at the last
    // level or before the deadline, whose check keeps the DP's time in reserve — so whenever it stops
    // there is a valid contour.
    int active = coarse_rays;
    for (int level = centroid_level + 1; level <= final_level && !out.deadline_hit; ++level) {
        const int first = table_.level_end(level - 1), last = table_.level_end(level);
        const int count = last - first;
        for (int k = 0; k < count; ++k) {
            const int r = table_.order(first + k);
            const int a = previous_active(r), b = next_active(r);
            const float la = lambda_out_[a], lb = lambda_out_[b];
            pending_[k] = r;
            pending_gap_[r] = static_cast<float>(std::hypot(la * table_.cos_at(a) - lb * table_.cos_at(b),
                                                            la * table_.sin_at(a) - lb * table_.sin_at(b)));
        }
        std::sort(pending_.begin(), pending_.begin() + count, [&](int x, int y) {
            return pending_gap_[x] > pending_gap_[y] || (pending_gap_[x] == pending_gap_[y] && x < y);
        });
        for (int shot = 0; shot < count; ++shot) {
            if (shot % kCheckEvery == 0) {
                const int batch = std::min(kCheckEvery, count - shot);
                const double need_ns = batch * ray_cost_ns + (active + batch) * node_cost_ns;
                if (clock.now() + std::chrono::nanoseconds(static_cast<long long>(need_ns)) > deadline) {
                    out.deadline_hit = true;
                    break;
                }
            }
            shoot(pending_[shot], image, m, prior, use_temporal, model);
            ++active;
        }
        if (!out.deadline_hit) levels = level + 1;
    }
    if (active > coarse_rays) {
        jumps_ = use_temporal && t_.jump_cost > 0.0;
        solve(prior.mean_radius(), prior);
        write_contour(m, out);
    }
    last_m_ = m;
    out.levels = levels;
}

bool ActiveRays::solve_without_jumps(const PolarPrior& prior, Contour& out) {
    if (!jumps_) return false;
    jumps_ = false;
    solve(prior.mean_radius(), prior);
    write_contour(last_m_, out);  // its levels, iterations and deadline as they were
    return true;
}

}  // namespace rays
