// SPDX-License-Identifier: Apache-2.0
#include "core/feature_window.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/frame_kernel.hpp"
#include "core/lanes.hpp"

namespace rays {
namespace {

constexpr float kGreyFloor = 2.0f;    // grey levels: the least spread a window's grey is divided by
constexpr float kChromaFloor = 4.0f;  // ... and its colour

constexpr int kN = FeatureWindow::kSize;
constexpr int kHalf = kN / 2;

// Where one coordinate of a window sample falls on a grid: the cell before it and the fraction
// beyond. The window's samples lie on a square lattice, so each column and each row is placed once.
struct GridPlace {
    int cell = 0;
    float frac = 0.0f;
};

// On the processing pixels, clamped as sample_bilinear() clamps.
GridPlace on_pixels(double x) {
    const double c = std::clamp(x, 0.0, kFrameSize - 1.001);
    const int i = static_cast<int>(c);
    return {i, static_cast<float>(c - i)};
}

// On the chroma pixels, whose centres lie at processing pixels 2i + 0.5.
GridPlace on_chroma(double x) {
    const double c = std::clamp((x - 0.5) * 0.5, 0.0, kChromaSize - 1.001);
    const int i = static_cast<int>(c);
    return {i, static_cast<float>(c - i)};
}

// Bilinear between the four grid values round (column, row) of a plane `stride` values wide.
template <typename T>
float blend_at(const T* plane, int stride, GridPlace column, GridPlace row) {
    const T* r0 = plane + row.cell * stride + column.cell;
    const T* r1 = r0 + stride;
    const float a = r0[0], b = r0[1], c = r1[0], d = r1[1];
    const float top = a + column.frac * (b - a);
    const float bottom = c + column.frac * (d - c);
    return top + row.frac * (bottom - top);
}

}  // namespace

FeatureWindow::FeatureWindow() {
    for (int u = 0; u < kN; ++u) hann_[u] = 0.5f * (1.0f - std::cos(2.0f * std::numbers::pi_v<float> * static_cast<float>(u) / kN));
    for (int k = 0; k < kOrientations; ++k) {
        const double a = 2.0 * std::numbers::pi * k / kOrientations;
        cos2_[k] = static_cast<float>(std::cos(a));
        sin2_[k] = static_cast<float>(std::sin(a));
    }
}

RAYS_FRAME_KERNEL
void FeatureWindow::fill(const FloatImage& image, const Chroma& chroma, Point centre, double window_px, int pairs,
                         std::array<Spectrum, kPairs>& out) {
    const double step = window_px / kN;
    const bool colour = chroma.present;
    std::array<GridPlace, kN> column_px, row_px, column_cell, row_cell;
    for (int k = 0; k < kN; ++k) {
        const double x = centre.x + (k - kHalf) * step, y = centre.y + (k - kHalf) * step;
        column_px[k] = on_pixels(x);
        row_px[k] = on_pixels(y);
        column_cell[k] = on_chroma(x);
        row_cell[k] = on_chroma(y);
    }
    double sum = 0.0, squares = 0.0;
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kN; ++u) {
            const float g = blend_at(image.px.data(), kFrameSize, column_px[u], row_px[v]);
            grey_[v * kN + u] = g;
            sum += g;
            squares += static_cast<double>(g) * g;
            if (colour) {
                cb_[v * kN + u] = blend_at(chroma.u.data(), kChromaSize, column_cell[u], row_cell[v]);
                cr_[v * kN + u] = blend_at(chroma.v.data(), kChromaSize, column_cell[u], row_cell[v]);
            }
        }
    const double count = kN * kN;
    const float mean = static_cast<float>(sum / count);
    const float grey_scale = 1.0f / std::max(kGreyFloor, static_cast<float>(std::sqrt(std::max(0.0, squares / count - mean * mean))));

    double magnitude_sum = 0.0;
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kN; ++u) {
            const int i = v * kN + u;
            gx_[i] = grey_[v * kN + std::min(u + 1, kN - 1)] - grey_[v * kN + std::max(u - 1, 0)];
            gy_[i] = grey_[std::min(v + 1, kN - 1) * kN + u] - grey_[std::max(v - 1, 0) * kN + u];
            magnitude_[i] = std::sqrt(gx_[i] * gx_[i] + gy_[i] * gy_[i]);
            magnitude_sum += magnitude_[i];
        }
    const float magnitude_scale = 1.0f / std::max(kGreyFloor, static_cast<float>(magnitude_sum / count));

    float u_mean = 128.0f, v_mean = 128.0f, chroma_scale = 0.0f;
    if (colour) {
        double su = 0.0, sv = 0.0, q = 0.0;
        for (int v = 0; v < kN; v += 2)
            for (int u = 0; u < kN; u += 2) {
                const float cb = cb_[v * kN + u], cr = cr_[v * kN + u];
                su += cb;
                sv += cr;
                q += static_cast<double>(cb) * cb + static_cast<double>(cr) * cr;
            }
        const double n = count / 4.0;
        u_mean = static_cast<float>(su / n);
        v_mean = static_cast<float>(sv / n);
        const double spread = std::sqrt(std::max(0.0, q / n - u_mean * u_mean - v_mean * v_mean));
        chroma_scale = 1.0f / std::max(kChromaFloor, static_cast<float>(spread));
    }

    // The channels, four samples of a row at a time in vector lanes (lanes.hpp), each lane doing
    // the scalar arithmetic.
    static_assert(kN % kLanes == 0, "a window row is whole groups of lanes");
    for (int v = 0; v < kN; ++v) {
        for (int u = 0; u < kN; u += kLanes) {
            const int i = v * kN + u;
            const Lanes w = load_lanes(&hann_[u]) * hann_[v];
            std::array<Lanes, 2 * kPairs> f{};
            f[0] = (load_lanes(&grey_[i]) - mean) * grey_scale;
            // Gradient orientations: channel k holds |g|·max(0, cos 2(θ − kπ/K)), from cos 2θ and
            // sin 2θ without an angle (unsigned orientation: a rim looks the same whichever side is
            // brighter); nothing where there is no gradient.
            const Lanes gx = load_lanes(&gx_[i]), gy = load_lanes(&gy_[i]), magnitude = load_lanes(&magnitude_[i]);
            const LaneIndex edge = magnitude > 0.0f;
            const Lanes cos2 = (gx * gx - gy * gy) / magnitude, sin2 = 2.0f * gx * gy / magnitude;
            for (int k = 0; k < kOrientations; ++k) {
                const Lanes along = cos2 * cos2_[k] + sin2 * sin2_[k];
                f[1 + k] = edge ? (along > 0.0f ? along : 0.0f) * magnitude_scale : Lanes{};
            }
            if (colour) {
                f[1 + kOrientations] = (load_lanes(&cb_[i]) - u_mean) * chroma_scale;
                f[2 + kOrientations] = (load_lanes(&cr_[i]) - v_mean) * chroma_scale;
            }
            // Each pair as complex numbers, (real, imaginary) side by side.
            for (int p = 0; p < pairs; ++p) {
                const Lanes re = w * f[2 * p], im = w * f[2 * p + 1];
                float* packed = reinterpret_cast<float*>(&out[p][i]);
                store_lanes(packed, __builtin_shufflevector(re, im, 0, 4, 1, 5));
                store_lanes(packed + kLanes, __builtin_shufflevector(re, im, 2, 6, 3, 7));
            }
        }
    }
}

}  // namespace rays
