// SPDX-License-Identifier: Apache-2.0
// Maps the chroma planes of a source frame onto the frame's 64×64 Chroma, over exactly the area the
// luma's AreaScaler maps onto 128×128: the luma crop, in chroma pixels (scaled by chroma / luma size,
// so 4:2:0 and 4:2:2 crops may start or end inside a chroma pixel), by area averaging with fractional
// edges. Each chroma output pixel covers the source area of its 2×2 processing pixels.
#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "core/image.hpp"
#include "io/area_filter.hpp"
#include "io/area_scaler.hpp"

namespace rays::io {

class ChromaScaler {
public:
    // `crop` is the luma crop resolved to the whole frame when w = 0 (AreaScaler::crop()). nullopt +
    // error when the chroma planes are empty or larger than the luma.
    static std::optional<ChromaScaler> make(int luma_w, int luma_h, int chroma_w, int chroma_h, const Crop& crop,
                                            std::string& error);

    // u and v point at the planes' top-left pixels; stride is their row pitch in bytes. Sets
    // out.present. Does not allocate.
    void scale(const std::uint8_t* u, const std::uint8_t* v, int stride, Chroma& out) const;

private:
    using Axis = AreaAxis<kChromaSize>;
    // Output pixel i of kChromaSize covers [begin + i·len/kChromaSize, begin + (i+1)·len/kChromaSize),
    // in chroma pixel edges, clipped to the plane's `size` pixels.
    static Axis make_axis(double begin, double len, int size);

    Axis cols_;
    Axis rows_;
};

}  // namespace rays::io
