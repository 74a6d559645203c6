// SPDX-License-Identifier: Apache-2.0
#include "core/appearance_model.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr int kLeastCells = 4;          // fewer target or background cells than this teach nothing
constexpr double kLeastRingPx = 4.0;    // the background ring is at least this wide
constexpr float kUnseen = 0.5f / AppearanceModel::kBins;  // a colour neither histogram has seen is 50:50

}  // namespace

int AppearanceModel::bin(const GreyImage& luma, const Chroma& chroma, int i, int j) {
    const int x = 2 * i, y = 2 * j;
    const int grey = (luma.at(x, y) + luma.at(x + 1, y) + luma.at(x, y + 1) + luma.at(x + 1, y + 1)) >> 2;
    const int cb = chroma.u_at(i, j) >> (8 - kChromaBits), cr = chroma.v_at(i, j) >> (8 - kChromaBits);
    return (((grey >> (8 - kLumaBits)) << kChromaBits | cb) << kChromaBits) | cr;
}

void AppearanceModel::fill_inside(const Contour& contour, int j0, int j1) {
    // Each edge's crossings of the cell rows' centre lines y = 2j + 0.5 it spans, in edge order.
    std::fill(crossing_count_.begin(), crossing_count_.begin() + (j1 - j0 + 1), 0);
    const int n = contour.size;
    for (int k = 0, prev = n - 1; k < n; prev = k++) {
        const Point& a = contour.points[k].p;
        const Point& b = contour.points[prev].p;
        const double low = std::min(a.y, b.y), high = std::max(a.y, b.y);
        const int first = std::max(j0, static_cast<int>(std::floor((low - 0.5) * 0.5)));
        const int last = std::min(j1, static_cast<int>(std::ceil((high - 0.5) * 0.5)));
        for (int j = first; j <= last; ++j) {
            const double yc = 2.0 * j + 0.5;
            int& count = crossing_count_[static_cast<std::size_t>(j - j0)];
            if ((a.y > yc) == (b.y > yc) || count == kMaxCrossings) continue;
            crossings_[static_cast<std::size_t>((j - j0) * kMaxCrossings + count++)] =
                static_cast<float>(a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y));
        }
    }
    for (int j = j0; j <= j1; ++j) {
        unsigned char* row = &inside_[static_cast<std::size_t>(j * kChromaSize)];
        std::fill(row, row + kChromaSize, 0);
        float* x = &crossings_[static_cast<std::size_t>((j - j0) * kMaxCrossings)];
        const int count = crossing_count_[static_cast<std::size_t>(j - j0)];
        for (int c = 1; c < count; ++c)  // insertion sort: a row crosses a contour a few times
            for (int at = c; at > 0 && x[at - 1] > x[at]; --at) std::swap(x[at - 1], x[at]);
        for (int c = 0; c + 1 < count; c += 2) {
            // Cells whose centre 2i + 0.5 lies between the two crossings.
            const int from = std::max(0, static_cast<int>(std::ceil((x[c] - 0.5f) * 0.5f)));
            const int to = std::min(kChromaSize - 1, static_cast<int>(std::floor((x[c + 1] - 0.5f) * 0.5f)));
            for (int i = from; i <= to; ++i) row[i] = 1;
        }
    }
}

RAYS_FRAME_KERNEL
bool AppearanceModel::learn(const GreyImage& luma, const Chroma& chroma, const Contour& contour, float rate) {
    if (!chroma.present || contour.size < 3) return false;
    double x0 = kFrameSize, y0 = kFrameSize, x1 = 0.0, y1 = 0.0;
    for (int k = 0; k < contour.size; ++k) {
        const Point& p = contour.points[k].p;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    const double ring = std::max(kLeastRingPx, std::sqrt(std::max(contour.area, 0.0) / std::numbers::pi));
    auto cell = [](double px) { return std::clamp(static_cast<int>(std::floor((px - 0.5) * 0.5)), 0, kChromaSize - 1); };
    const int i0 = cell(x0 - ring), i1 = cell(x1 + ring), j0 = cell(y0 - ring), j1 = cell(y1 + ring);
    fill_inside(contour, j0, j1);

    // A cell learns only if its 3×3 neighbourhood is all inside (the target) or all outside (the
    // background): the cells on the rim mix both.
    new_target_.fill(0.0f);
    new_background_.fill(0.0f);
    int targets = 0, backgrounds = 0;
    for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) {
            int inside = 0, seen = 0;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    const int u = i + di, v = j + dj;
                    if (u < 0 || v < 0 || u >= kChromaSize || v >= kChromaSize) continue;
                    ++seen;
                    // Rows beyond j0 … j1 lie beyond the ring, so outside the contour.
                    if (v >= j0 && v <= j1) inside += inside_[static_cast<std::size_t>(v * kChromaSize + u)];
                }
            if (inside == seen) {
                new_target_[bin(luma, chroma, i, j)] += 1.0f;
                ++targets;
            } else if (inside == 0) {
                new_background_[bin(luma, chroma, i, j)] += 1.0f;
                ++backgrounds;
            }
        }
    return blend(targets, backgrounds, rate);
}

template <typename Place>
bool AppearanceModel::seed_where(const GreyImage& luma, const Chroma& chroma, Place place) {
    if (!chroma.present) return false;
    new_target_.fill(0.0f);
    new_background_.fill(0.0f);
    int targets = 0, backgrounds = 0;
    for (int j = 0; j < kChromaSize; ++j)
        for (int i = 0; i < kChromaSize; ++i) {
            const int where = place(2.0 * i + 0.5, 2.0 * j + 0.5);  // the cell's centre
            if (where > 0) {
                new_target_[bin(luma, chroma, i, j)] += 1.0f;
                ++targets;
            } else if (where < 0) {
                new_background_[bin(luma, chroma, i, j)] += 1.0f;
                ++backgrounds;
            }
        }
    valid_ = false;
    return blend(targets, backgrounds, 1.0f);
}

bool AppearanceModel::seed(const GreyImage& luma, const Chroma& chroma, Point centre, double inside_px,
                           double ring_from_px, double ring_to_px) {
    return seed_where(luma, chroma, [&](double x, double y) {
        const double d = std::hypot(x - centre.x, y - centre.y);
        return d <= inside_px ? 1 : d >= ring_from_px && d <= ring_to_px ? -1 : 0;
    });
}

bool AppearanceModel::seed_box(const GreyImage& luma, const Chroma& chroma, const Box& box, double pad_px) {
    pad_px = std::max(pad_px, 2.0);  // a cell at least
    const double x0 = box.x - 0.5, y0 = box.y - 0.5, x1 = box.x + box.w - 0.5, y1 = box.y + box.h - 0.5;
    return seed_where(luma, chroma, [&](double x, double y) {
        if (x >= x0 && x <= x1 && y >= y0 && y <= y1) return 1;
        return x >= x0 - pad_px && x <= x1 + pad_px && y >= y0 - pad_px && y <= y1 + pad_px ? -1 : 0;
    });
}

bool AppearanceModel::blend(int targets, int backgrounds, float rate) {
    if (targets < kLeastCells || backgrounds < kLeastCells) return false;
    const float w = valid_ ? std::clamp(rate, 0.0f, 1.0f) : 1.0f;
    const float wt = w / static_cast<float>(targets), wb = w / static_cast<float>(backgrounds);
    for (int b = 0; b < kBins; ++b) {
        target_[b] = (1.0f - w) * target_[b] + wt * new_target_[b];
        background_[b] = (1.0f - w) * background_[b] + wb * new_background_[b];
    }
    odds_known_.fill(false);
    valid_ = true;
    return true;
}

float AppearanceModel::log_odds(int b) {
    if (!odds_known_[b]) {
        // Bayes with equal priors on the two histograms (Staple's P(O | x)), as log-odds.
        const float odds = std::log((target_[b] + kUnseen) / (background_[b] + kUnseen));
        log_odds_[b] = std::clamp(odds, -LikelihoodMap::kMaxLogOdds, LikelihoodMap::kMaxLogOdds);
        odds_known_[b] = true;
    }
    return log_odds_[b];
}

RAYS_FRAME_KERNEL
void AppearanceModel::likelihood(const GreyImage& luma, const Chroma& chroma, LikelihoodMap& out) {
    for (int j = 0; j < kChromaSize; ++j)
        for (int i = 0; i < kChromaSize; ++i)
            out.log_odds[static_cast<std::size_t>(j * kChromaSize + i)] = log_odds(bin(luma, chroma, i, j));
}

}  // namespace rays
