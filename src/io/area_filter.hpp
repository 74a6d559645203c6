// SPDX-License-Identifier: Apache-2.0
// The separable box filter both area scalers run: each output pixel of an N×N image is the weighted
// sum of the source pixels its row and column spans cover (weights summing to 1 per span), rounded.
// AreaScaler (luma, N = 128) and ChromaScaler (chroma, N = 64) differ only in how they make the spans.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace rays::io {

template <int N>
struct AreaAxis {
    struct Span {
        int first = 0;            // the first source pixel (relative to the origin handed to area_filter)
        int count = 0;
        std::size_t weights = 0;  // index of the first weight in `weights`
    };
    std::array<Span, N> spans;
    std::vector<float> weights;
};

// src points at the source pixel the spans count from; stride is its row pitch; out is N rows of N.
template <int N>
void area_filter(const AreaAxis<N>& rows, const AreaAxis<N>& cols, const std::uint8_t* src, int stride,
                 std::uint8_t* out) {
    for (int r = 0; r < N; ++r) {
        std::array<float, N> acc{};
        const auto& row_span = rows.spans[static_cast<std::size_t>(r)];
        for (int t = 0; t < row_span.count; ++t) {
            const std::uint8_t* line = src + static_cast<std::ptrdiff_t>(row_span.first + t) * stride;
            const float wy = rows.weights[row_span.weights + static_cast<std::size_t>(t)];
            for (int i = 0; i < N; ++i) {
                const auto& col_span = cols.spans[static_cast<std::size_t>(i)];
                const float* wx = &cols.weights[col_span.weights];
                const std::uint8_t* px = line + col_span.first;
                float sum = 0.0f;
                for (int u = 0; u < col_span.count; ++u) sum += wx[u] * px[u];
                acc[static_cast<std::size_t>(i)] += wy * sum;
            }
        }
        std::uint8_t* dst = out + static_cast<std::ptrdiff_t>(r) * N;
        for (int i = 0; i < N; ++i) {
            const float rounded = acc[static_cast<std::size_t>(i)] + 0.5f;  // acc >= 0: truncation rounds
            dst[i] = static_cast<std::uint8_t>(std::min(255, static_cast<int>(rounded)));
        }
    }
}

}  // namespace rays::io
