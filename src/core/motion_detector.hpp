// SPDX-License-Identifier: Apache-2.0
// Initialisation stage of the tracker (paper §4.1): with a static camera, the difference of two
// consecutive frames is smoothed (3×3 binomial, so the thin crescents of a slowly moving object survive
// the opening while pixel noise drops), thresholded, cleaned by a morphological opening and closing, and
// the centre of the largest changed region — together with the regions right beside it, as the leading
// and trailing crescents of one moving object — becomes the first reference point m of the active rays. Too many regions or
// one very large region means the threshold does not suit the noise: the result is rejected, the
// threshold raised or lowered, and detection repeated on the same pair. The threshold is kept from
// frame to frame, so it follows the noise of the scene.
#pragma once
#include <array>
#include <cstdint>

#include "core/image.hpp"
#include "core/tracker_config.hpp"

namespace rays {

struct Detection {
    bool found = false;
    Point centre;           // centroid of the chosen regions, processing pixels
    int area_px = 0;        // area of the largest region
    double radius_px = 0;   // half the geometric mean of the bounding box sides: a first contour size
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // bounding box of the chosen regions (inclusive)
    int regions = 0;        // regions >= min_area_px found in the accepted pass
    double threshold = 0;   // threshold used by the accepted pass
    int passes = 0;         // threshold passes run on this frame pair
    // When found is false, regions/threshold and the region fields describe the last, rejected pass.
};

class MotionDetector {
public:
    static constexpr int kMaxPasses = 6;  // threshold passes per frame pair at most

    MotionDetector();  // all buffers are members; nothing is allocated afterwards

    // Threshold back to the configured initial value (clamped to [threshold_min, threshold_max]).
    void reset(const DetectTunables& tunables);

    // Detect motion between the pair (previous, current). Never allocates; at most kMaxPasses passes.
    Detection detect(const GreyImage& previous, const GreyImage& current, const DetectTunables& tunables);

    double threshold() const { return threshold_; }  // the adapted threshold, kept between frames

    // Whether `in(centre)` holds for the centroid of any region the last detect() found, not only of
    // those it chose (the largest and the regions next to it): a slow mover beside a bigger one.
    template <class In>
    bool any_region(In in) const {
        for (int i = 0; i < described_; ++i) {
            const Region& r = regions_[static_cast<std::size_t>(i)];
            if (in(Point{static_cast<double>(r.sum_x) / r.area, static_cast<double>(r.sum_y) / r.area})) return true;
        }
        return false;
    }

private:
    using Mask = Plane<std::uint8_t>;  // 1 where the grey value changed
    static constexpr int kMaxRegions = 64;  // regions described per pass; more only get counted
    struct Region {
        int area, sum_x, sum_y, x0, y0, x1, y1;
    };

    // One pass at a fixed threshold: binary difference, opening, closing, regions.
    Detection run_pass(double threshold, int min_area_px);

    Plane<float> difference_, smoothed_difference_;
    std::array<Region, kMaxRegions> regions_{};
    int described_ = 0;  // of regions_, those the last pass found
    Mask mask_;
    Mask work_;
    Mask filter_tmp_;
    std::array<std::int32_t, kFramePixels> fill_stack_{};  // flood fill: each pixel is pushed at most once
    double threshold_;
};

}  // namespace rays
