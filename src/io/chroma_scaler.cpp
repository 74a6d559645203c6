// SPDX-License-Identifier: Apache-2.0
#include "io/chroma_scaler.hpp"

#include <algorithm>
#include <cmath>

namespace rays::io {

ChromaScaler::Axis ChromaScaler::make_axis(double begin, double len, int size) {
    Axis axis;
    const double step = len / kChromaSize;
    for (int i = 0; i < kChromaSize; ++i) {
        const double a = begin + i * step, b = begin + (i + 1) * step;
        const int first = std::clamp(static_cast<int>(std::floor(a)), 0, size - 1);
        const int stop = std::clamp(static_cast<int>(std::ceil(b)), first + 1, size);
        Axis::Span& span = axis.spans[static_cast<std::size_t>(i)];
        span.first = first;
        span.count = stop - first;
        span.weights = axis.weights.size();
        double total = 0.0;
        for (int j = first; j < stop; ++j) total += std::max(0.0, std::min(b, j + 1.0) - std::max(a, 1.0 * j));
        for (int j = first; j < stop; ++j) {
            const double overlap = std::max(0.0, std::min(b, j + 1.0) - std::max(a, 1.0 * j));
            axis.weights.push_back(static_cast<float>(total > 0.0 ? overlap / total : 1.0 / span.count));
        }
    }
    return axis;
}

std::optional<ChromaScaler> ChromaScaler::make(int luma_w, int luma_h, int chroma_w, int chroma_h, const Crop& crop,
                                               std::string& error) {
    if (chroma_w < 1 || chroma_h < 1 || chroma_w > luma_w || chroma_h > luma_h) {
        error = "chroma planes " + std::to_string(chroma_w) + "x" + std::to_string(chroma_h) + " do not fit a " +
                std::to_string(luma_w) + "x" + std::to_string(luma_h) + " luma plane";
        return std::nullopt;
    }
    const double sx = static_cast<double>(chroma_w) / luma_w, sy = static_cast<double>(chroma_h) / luma_h;
    ChromaScaler scaler;
    scaler.cols_ = make_axis(crop.x * sx, crop.w * sx, chroma_w);
    scaler.rows_ = make_axis(crop.y * sy, crop.h * sy, chroma_h);
    return scaler;
}

void ChromaScaler::scale(const std::uint8_t* u, const std::uint8_t* v, int stride, Chroma& out) const {
    area_filter(rows_, cols_, u, stride, out.u.data());
    area_filter(rows_, cols_, v, stride, out.v.data());
    out.present = true;
}

}  // namespace rays::io
