// SPDX-License-Identifier: Apache-2.0
// Maps a crop of the source frame onto the 128×128 processing frame by exact area averaging.
//
// Convention (pixel centres at integers on both sides): source = processing * scale + offset with
// scale = crop_w / 128 and offset = crop_x + (scale - 1) / 2, and likewise in y.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/image.hpp"
#include "io/area_filter.hpp"

namespace rays::io {

struct Crop {
    int x = 0;
    int y = 0;
    int w = 0;  // 0: the whole frame (then x, y and h must be 0 too)
    int h = 0;
};

class AreaScaler {
public:
    // Validates the crop against the source size and precomputes the filter. nullopt + error if out of bounds.
    static std::optional<AreaScaler> make(int src_w, int src_h, Crop crop, std::string& error);

    // src points at the source frame's top-left pixel (not the crop's); src_stride is its row pitch in
    // bytes. Does not allocate.
    void scale(const std::uint8_t* src, int src_stride, GreyImage& out) const;

    double scale_x() const { return static_cast<double>(crop_.w) / kFrameSize; }
    double scale_y() const { return static_cast<double>(crop_.h) / kFrameSize; }
    double offset_x() const { return crop_.x + (scale_x() - 1.0) / 2.0; }
    double offset_y() const { return crop_.y + (scale_y() - 1.0) / 2.0; }
    const Crop& crop() const { return crop_; }

private:
    // The source pixels (relative to the crop) each processing pixel covers in one axis, with their weights.
    using Axis = AreaAxis<kFrameSize>;
    static Axis make_axis(int crop_len);

    Crop crop_;
    Axis cols_;
    Axis rows_;
};

}  // namespace rays::io
