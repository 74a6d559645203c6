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
        Span& span = axis.spans[static_cast<std::size_t>(i)];
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

// Separable box filter, as AreaScaler's.
void ChromaScaler::scale_plane(const std::uint8_t* src, int stride, std::array<std::uint8_t, kChromaPixels>& out) const {
    for (int r = 0; r < kChromaSize; ++r) {
        std::array<float, kChromaSize> acc{};
        const Span& row_span = rows_.spans[static_cast<std::size_t>(r)];
        for (int t = 0; t < row_span.count; ++t) {
            const std::uint8_t* line = src + static_cast<std::ptrdiff_t>(row_span.first + t) * stride;
            const float wy = rows_.weights[row_span.weights + static_cast<std::size_t>(t)];
            for (int i = 0; i < kChromaSize; ++i) {
                const Span& col_span = cols_.spans[static_cast<std::size_t>(i)];
                const float* wx = &cols_.weights[col_span.weights];
                const std::uint8_t* px = line + col_span.first;
                float sum = 0.0f;
                for (int u = 0; u < col_span.count; ++u) sum += wx[u] * px[u];
                acc[static_cast<std::size_t>(i)] += wy * sum;
            }
        }
        std::uint8_t* dst = out.data() + r * kChromaSize;
        for (int i = 0; i < kChromaSize; ++i)
            dst[i] = static_cast<std::uint8_t>(std::min(255, static_cast<int>(acc[static_cast<std::size_t>(i)] + 0.5f)));
    }
}

void ChromaScaler::scale(const std::uint8_t* u, const std::uint8_t* v, int stride, Chroma& out) const {
    scale_plane(u, stride, out.u);
    scale_plane(v, stride, out.v);
    out.present = true;
}

}  // namespace rays::io
