// The fixed 128×128 processing frame. x right, y down, pixel centres at integer coordinates.
#pragma once
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

struct Point {
    double x = 0.0;
    double y = 0.0;
};

}  // namespace rays
