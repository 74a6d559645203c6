// SPDX-License-Identifier: Apache-2.0
#include "core/motion_detector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

using Mask = Plane<std::uint8_t>;
using FillStack = std::array<std::int32_t, kFramePixels>;

constexpr double kRaiseFactor = 1.5;   // after a pass with too many or too large regions
constexpr double kLowerFactor = 0.75;  // after a pass without any region

double clamp_threshold(double threshold, const DetectTunables& tunables) {
    return std::max(tunables.threshold_min, std::min(threshold, tunables.threshold_max));
}

// Raise the threshold after a noisy pass, lower it after an empty one. The mask only shrinks as the
// threshold grows, so once both kinds of pass have been seen the answer lies between them: bisect
// rather than step past the other one.
double next_threshold(double threshold, bool too_noisy, double highest_noisy, double lowest_empty,
                      const DetectTunables& tunables) {
    double next = too_noisy ? threshold * kRaiseFactor : threshold * kLowerFactor;
    if (too_noisy && next >= lowest_empty) next = 0.5 * (threshold + lowest_empty);
    if (!too_noisy && next <= highest_noisy) next = 0.5 * (threshold + highest_noisy);
    return clamp_threshold(next, tunables);
}

constexpr int kMergeGapPx = 6;  // regions this close to the largest belong to the same object
constexpr int kCrescentAreaRatio = 3;   // two crescents of one object differ in area by less than this factor ...
constexpr int kCrescentGapLengths = 5;  // ... and lie no more than this many half-lengths apart (the opening shortens them)

constexpr double kNoiseFactor = 4.0;  // a change must stand this many noise σ above zero

// Signed difference smoothed by a 3×3 binomial filter (borders replicated), stored as |·| in
// `smoothed`. Returns the noise σ of that image, estimated robustly as 1.4826 × its median.
double smoothed_difference(const GreyImage& previous, const GreyImage& current, Plane<float>& difference,
                           Plane<float>& smoothed) {
    for (std::size_t i = 0; i < difference.px.size(); ++i)
        difference.px[i] = static_cast<float>(int{current.px[i]} - int{previous.px[i]});
    for (int y = 0; y < kFrameSize; ++y) {
        const float* in = difference.row(y);
        float* out = smoothed.row(y);
        constexpr int last = kFrameSize - 1;
        out[0] = 0.25f * in[0] + 0.5f * in[0] + 0.25f * in[1];
        for (int x = 1; x < last; ++x) out[x] = 0.25f * in[x - 1] + 0.5f * in[x] + 0.25f * in[x + 1];  // vectorises
        out[last] = 0.25f * in[last - 1] + 0.5f * in[last] + 0.25f * in[last];
    }
    std::array<int, 256> histogram{};
    for (int y = 0; y < kFrameSize; ++y) {
        const float* above = smoothed.row(y > 0 ? y - 1 : y);
        const float* centre = smoothed.row(y);
        const float* below = smoothed.row(y + 1 < kFrameSize ? y + 1 : y);
        float* out = difference.row(y);
        for (int x = 0; x < kFrameSize; ++x) {
            out[x] = std::abs(0.25f * above[x] + 0.5f * centre[x] + 0.25f * below[x]);
            ++histogram[static_cast<std::size_t>(std::min(255.0f, out[x]))];
        }
    }
    std::swap(difference, smoothed);
    int seen = 0, median = 0;
    while (median < 255 && (seen += histogram[static_cast<std::size_t>(median)]) < kFramePixels / 2) ++median;
    return 1.4826 * (median + 0.5);
}

void threshold_difference(const Plane<float>& magnitude, double threshold, Mask& mask) {
    const float t = static_cast<float>(threshold);
    for (std::size_t i = 0; i < mask.px.size(); ++i) mask.px[i] = static_cast<std::uint8_t>(magnitude.px[i] > t);
}

// The leading and trailing crescents of one uniform object moving slowly are two thin regions with the
// object between them, as far apart as the object is wide: side by side along one axis, overlapping by
// most of their extent along the other, longer along it than across (by half at least), alike in
// size, and not much further apart than they are long.
template <class Region>
bool facing(const Region& a, const Region& b) {
    auto faces = [](int a0, int a1, int b0, int b1, int c0, int c1, int d0, int d1) {
        const int overlap = std::min(a1, b1) - std::max(a0, b0) + 1;  // along the crescents
        const int shorter = std::min(a1 - a0, b1 - b0) + 1, longer = std::max(a1 - a0, b1 - b0) + 1;
        const int gap = std::max(c0 - d1, d0 - c1) - 1;                // across them
        const bool thin = 2 * (a1 - a0 + 1) >= 3 * (c1 - c0 + 1) && 2 * (b1 - b0 + 1) >= 3 * (d1 - d0 + 1);
        return thin && 2 * overlap >= longer && shorter * 2 >= longer && gap >= 0 && 2 * gap <= kCrescentGapLengths * shorter;
    };
    const bool alike = std::min(a.area, b.area) * kCrescentAreaRatio >= std::max(a.area, b.area);
    return alike && (faces(a.y0, a.y1, b.y0, b.y1, a.x0, a.x1, b.x0, b.x1) ||
                     faces(a.x0, a.x1, b.x0, b.x1, a.y0, a.y1, b.y0, b.y1));
}

// 3x3 square structuring element, applied separably (rows, then columns). Outside the frame the
// element is clipped: border pixels are judged by their in-frame neighbours only.
template <class Combine>
void filter_3x3(const Mask& src, Mask& tmp, Mask& dst, Combine combine) {
    for (int y = 0; y < kFrameSize; ++y) {
        const std::uint8_t* in = src.row(y);
        std::uint8_t* out = tmp.row(y);
        out[0] = combine(in[0], in[1]);
        for (int x = 1; x + 1 < kFrameSize; ++x) out[x] = combine(combine(in[x], in[x - 1]), in[x + 1]);  // vectorises
        out[kFrameSize - 1] = combine(in[kFrameSize - 1], in[kFrameSize - 2]);
    }
    for (int y = 0; y < kFrameSize; ++y) {
        const std::uint8_t* above = tmp.row(y > 0 ? y - 1 : y);
        const std::uint8_t* centre = tmp.row(y);
        const std::uint8_t* below = tmp.row(y + 1 < kFrameSize ? y + 1 : y);
        std::uint8_t* out = dst.row(y);
        for (int x = 0; x < kFrameSize; ++x) out[x] = combine(combine(above[x], centre[x]), below[x]);
    }
}

void erode(const Mask& src, Mask& tmp, Mask& dst) {
    filter_3x3(src, tmp, dst, [](std::uint8_t a, std::uint8_t b) { return std::min(a, b); });
}

void dilate(const Mask& src, Mask& tmp, Mask& dst) {
    filter_3x3(src, tmp, dst, [](std::uint8_t a, std::uint8_t b) { return std::max(a, b); });
}

// 8-connected components by iterative flood fill; clears the mask as it goes. Describes the regions
// of at least min_area_px pixels (the first kMaxRegions of them; the rest are only counted).
template <class Region, std::size_t N>
int find_regions(Mask& mask, FillStack& stack, int min_area_px, std::array<Region, N>& regions, int& described) {
    int count = 0;
    described = 0;
    for (int start = 0; start < kFramePixels; ++start) {
        if (!mask.px[static_cast<std::size_t>(start)]) continue;
        mask.px[static_cast<std::size_t>(start)] = 0;
        int top = 0;
        stack[static_cast<std::size_t>(top++)] = start;
        Region r{0, 0, 0, kFrameSize, kFrameSize, -1, -1};
        while (top > 0) {
            const int p = stack[static_cast<std::size_t>(--top)];
            const int x = p % kFrameSize, y = p / kFrameSize;
            ++r.area;
            r.sum_x += x;
            r.sum_y += y;
            r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x);
            r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
            for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, kFrameSize - 1); ++ny) {
                for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, kFrameSize - 1); ++nx) {
                    std::uint8_t& neighbour = mask.at(nx, ny);
                    if (!neighbour) continue;
                    neighbour = 0;  // cleared on push, so the stack never holds a pixel twice
                    stack[static_cast<std::size_t>(top++)] = ny * kFrameSize + nx;
                }
            }
        }
        if (r.area < min_area_px) continue;
        ++count;
        if (described < static_cast<int>(N)) regions[static_cast<std::size_t>(described++)] = r;
    }
    return count;
}

// The largest region (the first on a tie) together with the regions close to it: one moving object.
template <class Region, std::size_t N>
Detection describe_largest(const std::array<Region, N>& regions, int described, int count) {
    Detection best;
    best.regions = count;
    if (described == 0) return best;
    const Region* largest = regions.data();
    for (int i = 1; i < described; ++i)
        if (regions[i].area > largest->area) largest = &regions[i];
    // Grow the chosen set from the largest region: any region within kMergeGapPx of the set's
    // bounding box joins it, until none does (at most `described` rounds).
    std::array<bool, N> taken{};
    long area = 0, sum_x = 0, sum_y = 0;
    int x0 = largest->x0, y0 = largest->y0, x1 = largest->x1, y1 = largest->y1;
    for (bool grew = true; grew;) {
        grew = false;
        for (int i = 0; i < described; ++i) {
            const Region& r = regions[i];
            if (taken[static_cast<std::size_t>(i)]) continue;
            const bool near = r.x0 <= x1 + kMergeGapPx && r.x1 >= x0 - kMergeGapPx && r.y0 <= y1 + kMergeGapPx &&
                              r.y1 >= y0 - kMergeGapPx;
            if (!near && !facing(*largest, r)) continue;
            taken[static_cast<std::size_t>(i)] = grew = true;
            area += r.area;
            sum_x += r.sum_x;
            sum_y += r.sum_y;
            x0 = std::min(x0, r.x0), y0 = std::min(y0, r.y0), x1 = std::max(x1, r.x1), y1 = std::max(y1, r.y1);
        }
    }
    best.area_px = largest->area;
    best.centre = {static_cast<double>(sum_x) / static_cast<double>(area), static_cast<double>(sum_y) / static_cast<double>(area)};
    best.radius_px = 0.5 * std::sqrt(static_cast<double>(x1 - x0 + 1) * (y1 - y0 + 1));
    best.x0 = x0, best.y0 = y0, best.x1 = x1, best.y1 = y1;
    return best;
}

}  // namespace

MotionDetector::MotionDetector() : threshold_(clamp_threshold(DetectTunables{}.threshold, DetectTunables{})) {}

void MotionDetector::reset(const DetectTunables& tunables) {
    threshold_ = clamp_threshold(tunables.threshold, tunables);
}

Detection MotionDetector::run_pass(double threshold, int min_area_px) {
    threshold_difference(smoothed_difference_, threshold, mask_);
    erode(mask_, filter_tmp_, work_);  // opening: removes changes narrower than 3 px
    dilate(work_, filter_tmp_, mask_);
    dilate(mask_, filter_tmp_, work_);  // closing: fills gaps narrower than 3 px
    erode(work_, filter_tmp_, mask_);
    int described = 0;
    const int count = find_regions(mask_, fill_stack_, min_area_px, regions_, described);
    described_ = described;
    Detection pass = describe_largest(regions_, described, count);
    pass.threshold = threshold;
    return pass;
}

RAYS_FRAME_KERNEL
Detection MotionDetector::detect(const GreyImage& previous, const GreyImage& current,
                                 const DetectTunables& tunables) {
    const double max_area_px = tunables.max_area_fraction * kFramePixels;
    double highest_noisy = -std::numeric_limits<double>::infinity();
    double lowest_empty = std::numeric_limits<double>::infinity();
    // The threshold kept from the last frame, but never above what this pair's own noise calls for.
    const double noise = smoothed_difference(previous, current, difference_, smoothed_difference_);
    threshold_ = clamp_threshold(std::min(threshold_, kNoiseFactor * noise), tunables);
    Detection result;
    for (int pass = 1; pass <= kMaxPasses; ++pass) {
        result = run_pass(threshold_, tunables.min_area_px);
        result.passes = pass;
        // §4.1: too many small regions or one very large region: the threshold does not suit the noise.
        const bool too_noisy = result.regions > tunables.max_regions || result.area_px > max_area_px;
        const bool empty = result.regions == 0;
        if (!too_noisy && !empty) {
            result.found = true;
            return result;
        }
        if (too_noisy) highest_noisy = std::max(highest_noisy, threshold_);
        else lowest_empty = std::min(lowest_empty, threshold_);
        const double next = next_threshold(threshold_, too_noisy, highest_noisy, lowest_empty, tunables);
        if (next == threshold_) break;  // pinned at a bound: another pass would repeat this one
        threshold_ = next;
    }
    described_ = 0;  // a rejected pass's regions are not what was found
    return result;
}

}  // namespace rays
