// SPDX-License-Identifier: Apache-2.0
// The fixed 128×128 processing frame. x right, y down, pixel centres at integer coordinates.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>

namespace rays {

inline constexpr int kFrameSize = 128;
inline constexpr int kFramePixels = kFrameSize * kFrameSize;

template <class T>
struct Plane {
    std::array<T, kFramePixels> px{};

    T& at(int x, int y) { return px[static_cast<std::size_t>(y * kFrameSize + x)]; }
    const T& at(int x, int y) const { return px[static_cast<std::size_t>(y * kFrameSize + x)]; }
    T* row(int y) { return px.data() + y * kFrameSize; }
    const T* row(int y) const { return px.data() + y * kFrameSize; }
};

using GreyImage = Plane<std::uint8_t>;   // what a frame source delivers
using FloatImage = Plane<float>;         // the smoothed image the rays sample

// The image at (x, y), bilinear between pixel centres; a point off the image reads its border.
template <class T>
float sample_bilinear(const Plane<T>& image, double x, double y) {
    const double cx = std::clamp(x, 0.0, kFrameSize - 1.001), cy = std::clamp(y, 0.0, kFrameSize - 1.001);
    const int i = static_cast<int>(cx), j = static_cast<int>(cy);
    const float fx = static_cast<float>(cx - i), fy = static_cast<float>(cy - j);
    const T* r0 = image.row(j) + i;
    const T* r1 = r0 + kFrameSize;
    const float a = r0[0], b = r0[1], c = r1[0], d = r1[1];
    const float top = a + fx * (b - a);
    const float bottom = c + fx * (d - c);
    return top + fy * (bottom - top);
}

// The frame's colour beside its luma, where the source has colour: Cb (u) and Cr (v), full-range
// BT.601 as in JPEG (128 = no colour), each 64×64, chroma pixel (i, j) covering processing pixels
// 2i..2i+1 × 2j..2j+1 of the same crop. A mono source leaves `present` false.
inline constexpr int kChromaSize = kFrameSize / 2;
inline constexpr int kChromaPixels = kChromaSize * kChromaSize;

struct Chroma {
    std::array<std::uint8_t, kChromaPixels> u{};
    std::array<std::uint8_t, kChromaPixels> v{};
    bool present = false;

    std::uint8_t u_at(int x, int y) const { return u[static_cast<std::size_t>(y * kChromaSize + x)]; }
    std::uint8_t v_at(int x, int y) const { return v[static_cast<std::size_t>(y * kChromaSize + x)]; }
};

struct Point {
    double x = 0.0;
    double y = 0.0;
};

}  // namespace rays
