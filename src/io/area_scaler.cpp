// SPDX-License-Identifier: Apache-2.0
#include "io/area_scaler.hpp"

#include <algorithm>

namespace rays::io {

// Processing pixel i covers the source interval [i·L/128, (i+1)·L/128) of a crop L pixels long, in
// pixel-edge coordinates. Each source pixel j it touches weighs its overlap with that interval divided
// by the interval's length L/128. Computed in units of 1/128 pixel, the overlaps are exact integers.
AreaScaler::Axis AreaScaler::make_axis(int crop_len) {
    Axis axis;
    const long long len = crop_len;
    for (int i = 0; i < kFrameSize; ++i) {
        const long long begin = i * len;        // in 1/128 pixel
        const long long end = (i + 1) * len;
        const int first = static_cast<int>(begin / kFrameSize);
        const int stop = static_cast<int>((end + kFrameSize - 1) / kFrameSize);
        Axis::Span& span = axis.spans[static_cast<std::size_t>(i)];
        span.first = first;
        span.count = stop - first;
        span.weights = axis.weights.size();
        for (int j = first; j < stop; ++j) {
            const long long overlap = std::min(end, (j + 1LL) * kFrameSize) - std::max(begin, 1LL * j * kFrameSize);
            axis.weights.push_back(static_cast<float>(static_cast<double>(overlap) / static_cast<double>(len)));
        }
    }
    return axis;
}

std::optional<AreaScaler> AreaScaler::make(int src_w, int src_h, Crop crop, std::string& error) {
    if (src_w < 1 || src_h < 1) {
        error = "source size " + std::to_string(src_w) + "x" + std::to_string(src_h) + " is empty";
        return std::nullopt;
    }
    if (crop.w == 0) {
        if (crop.x != 0 || crop.y != 0 || crop.h != 0) {
            error = "crop with w = 0 (whole frame) must have x = y = h = 0";
            return std::nullopt;
        }
        crop = Crop{0, 0, src_w, src_h};
    }
    if (crop.x < 0 || crop.y < 0 || crop.w < 1 || crop.h < 1 || crop.x > src_w - crop.w || crop.y > src_h - crop.h) {
        error = "crop " + std::to_string(crop.w) + "x" + std::to_string(crop.h) + "+" + std::to_string(crop.x) + "+" +
                std::to_string(crop.y) + " is not inside the " + std::to_string(src_w) + "x" + std::to_string(src_h) +
                " source frame";
        return std::nullopt;
    }
    AreaScaler scaler;
    scaler.crop_ = crop;
    scaler.cols_ = make_axis(crop.w);
    scaler.rows_ = make_axis(crop.h);
    return scaler;
}

void AreaScaler::scale(const std::uint8_t* src, int src_stride, GreyImage& out) const {
    const std::uint8_t* crop_origin = src + static_cast<std::ptrdiff_t>(crop_.y) * src_stride + crop_.x;
    area_filter(rows_, cols_, crop_origin, src_stride, out.px.data());
}

}  // namespace rays::io
