// SPDX-License-Identifier: Apache-2.0
// What the correlation filter sees of a square window round the target: per window sample, grey,
// unsigned gradient orientations (HOG-like, soft-binned without cells) and, where the source has
// colour, Cb and Cr. Each channel is brought to the window's own scale (grey and colour to their
// spread, the orientations to the mean gradient), so that a change of light or contrast does not
// change the target's looks, and tapered by a Hann window for the transforms that follow. Fixed
// memory; nothing is allocated.
#pragma once
#include <array>
#include <complex>

#include "core/image.hpp"

namespace rays {

class FeatureWindow {
public:
    static constexpr int kSize = 32;  // window samples per side (a power of two: radix-2/4 FFTs)
    static constexpr int kOrientations = 6;
    static constexpr int kChannels = 1 + kOrientations + 2;  // grey, orientations, Cb, Cr
    static constexpr int kPairs = (kChannels + 1) / 2;       // two real channels per complex plane
    using Spectrum = std::array<std::complex<float>, kSize * kSize>;

    FeatureWindow();

    // The window of side `window_px` (processing pixels) centred at `centre`, kSize samples a side:
    // the first `pairs` pairs of channels, each pair as one complex plane, out[p] holding channel 2p
    // (real) and 2p + 1 (imaginary). Without colour the chroma channels are not filled.
    void fill(const FloatImage& image, const Chroma& chroma, Point centre, double window_px, int pairs,
              std::array<Spectrum, kPairs>& out);

private:
    using Plane = std::array<float, kSize * kSize>;

    std::array<float, kSize> hann_{};
    std::array<float, kOrientations> cos2_{}, sin2_{};  // cos 2θ_k and sin 2θ_k of each orientation bin
    Plane grey_{}, gx_{}, gy_{}, magnitude_{};  // the window's samples and their gradient
    Plane cb_{}, cr_{};                         // ... and their colour (colour sources)
};

}  // namespace rays
