// SPDX-License-Identifier: Apache-2.0
// Finds the target by what it looks like, not by its edges: a multi-channel discriminative
// correlation filter (MOSSE, Bolme et al., CVPR 2010, with the multi-channel closed form of DSST,
// Danelljan et al., BMVC 2014) over a square window round the target, learned where the contour is.
// Its features (grey, gradient orientations, colour) are core/feature_window.hpp's. The window's side
// follows the contour's size, so the filter is learned and applied at the target's scale. The
// response's peak-to-sidelobe ratio is the match's confidence. Fixed memory; the FFT's tables are
// made at construction, so locate() and learn() allocate nothing.
#pragma once
#include <array>
#include <complex>

#include "core/feature_window.hpp"
#include "core/fft_columns.hpp"
#include "core/image.hpp"

namespace rays {

struct FilterMatch {
    Point at;          // where the window's target centre is found, processing pixels
    double psr = 0.0;  // peak-to-sidelobe ratio of the response (0: no filter yet)
};

class CorrelationFilter {
public:
    static constexpr int kSize = FeatureWindow::kSize;
    static constexpr int kOrientations = FeatureWindow::kOrientations;
    static constexpr int kChannels = FeatureWindow::kChannels;
    static constexpr int kPairs = FeatureWindow::kPairs;
    static constexpr double kPadding = 2.5;  // window side / target size (target and its surroundings)
    static constexpr double kConfidentPsr = 5.0;  // a match this clear of its sidelobe says where the target is

    CorrelationFilter();

    void reset() { valid_ = false; }
    // What `other` has learned (its filter and window size), without its FFT tables and scratch
    // planes: about a quarter of what a whole copy moves.
    void copy_learned(const CorrelationFilter& other);
    bool valid() const { return valid_; }
    double window_px() const { return window_px_; }

    // Learns the target centred at `centre` whose size (its equivalent diameter) is `target_px`,
    // blended in at `rate` (a new filter after reset() replaces it). The window's side follows the
    // size at the same rate.
    void learn(const FloatImage& image, const Chroma& chroma, Point centre, double target_px, float rate);
    // The same on the frame locate() last looked at, from the window it transformed there (no
    // transform of its own: the wanted response is moved to where the target is in that window).
    // A target beyond a quarter of the window from its centre is learned from a window of its own.
    void learn_located(const FloatImage& image, const Chroma& chroma, Point centre, double target_px, float rate);

    // The response over a window centred at `around`: where its peak is, and how sure. A target
    // whose centre is found off the frame is not found there (PSR 0): what the frame shows of it
    // is not where it is, and a track cannot start from it.
    FilterMatch locate(const FloatImage& image, const Chroma& chroma, Point around);

private:
    using Complex = std::complex<float>;
    static constexpr int kHalfColumns = kSize / 2 + 1;  // u = 0 … N/2: real features mirror the rest
    using Spectrum = FeatureWindow::Spectrum;
    using HalfSpectrum = std::array<Complex, kSize * kHalfColumns>;  // row v, column u ≤ N/2
    using Plane = std::array<float, kSize * kSize>;

    // The window's features at `centre`, transformed: features_[c] is channel c's half spectrum.
    void transform_window(const FloatImage& image, const Chroma& chroma, Point centre);
    // Blends the transformed window into the filter with the wanted response G·ramp (the label
    // moved by the target's displacement in the window).
    void blend(double du, double dv, bool fresh, float rate);
    void fft2(Spectrum& plane);
    // The real plane whose half spectrum is `half` (unscaled inverse).
    void inverse_real(const HalfSpectrum& half, Plane& out);

    FeatureWindow window_;  // the window's features, pairs of channels packed into pairs_
    FftColumns fft_;
    Plane re_{}, im_{}, re_across_{}, im_across_{};  // the transforms' split planes, as laid out and transposed
    std::array<Spectrum, kPairs> pairs_{};
    std::array<HalfSpectrum, kChannels> features_{};
    std::array<HalfSpectrum, kChannels> numerator_{};  // A_l = G · conj(F_l), learned
    std::array<float, kSize * kHalfColumns> denominator_{};  // B = Σ_l |F_l|², learned
    HalfSpectrum label_{};  // G: the Gaussian the response should be, peaked at displacement 0
    HalfSpectrum response_spectrum_{};
    Plane response_{};
    std::array<Complex, kSize> ramp_u_{}, ramp_v_{};
    Point window_centre_;  // where the last transformed window was centred
    bool window_colour_ = false;  // ... and whether it had chroma channels
    bool colour_ = false;  // the filter was learned with chroma channels
    bool valid_ = false;
    double window_px_ = 0.0;
};

}  // namespace rays
