// SPDX-License-Identifier: Apache-2.0
#include "core/correlation_filter.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "common/frame_kernel.hpp"

namespace rays {
namespace {

constexpr double kMinWindowPx = 24.0;   // a window this small still holds a small target and some ground
constexpr double kMaxWindowPx = 128.0;  // ... and none larger than the frame
constexpr double kLabelSigma = 0.1;     // of the target's size in samples: the wanted response's width
constexpr float kLambda = 0.01f;        // regulariser, per window sample (features have unit spread)
constexpr int kPeakExclusion = 3;       // samples either side of the peak not counted as its sidelobe

constexpr int kN = CorrelationFilter::kSize;
constexpr int kHalf = kN / 2;

}  // namespace

CorrelationFilter::CorrelationFilter() {
    // The response wanted for a target at the window's centre: a Gaussian at displacement 0 (the
    // indices wrap), so that the found peak's index is the target's displacement.
    const double sigma = kLabelSigma * kN / kPadding;
    Spectrum& label = pairs_[0];
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kN; ++u) {
            const int du = u < kHalf ? u : u - kN, dv = v < kHalf ? v : v - kN;
            label[v * kN + u] = static_cast<float>(std::exp(-(du * du + dv * dv) / (2.0 * sigma * sigma)));
        }
    fft2(label);
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kHalfColumns; ++u) label_[v * kHalfColumns + u] = label[v * kN + u];
}

void CorrelationFilter::copy_learned(const CorrelationFilter& other) {
    numerator_ = other.numerator_;
    denominator_ = other.denominator_;
    colour_ = other.colour_;
    valid_ = other.valid_;
    window_px_ = other.window_px_;
}

RAYS_FRAME_KERNEL
void CorrelationFilter::fft2(Spectrum& plane) {
    // Along the rows: the plane transposed, so that its rows are the columns transformed.
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kN; ++u) {
            re_across_[u * kN + v] = plane[v * kN + u].real();
            im_across_[u * kN + v] = plane[v * kN + u].imag();
        }
    fft_.run(re_across_.data(), im_across_.data(), kN, kN, FftColumns::Direction::Forward);
    // Along the columns: transposed back.
    for (int u = 0; u < kN; ++u)
        for (int v = 0; v < kN; ++v) {
            re_[v * kN + u] = re_across_[u * kN + v];
            im_[v * kN + u] = im_across_[u * kN + v];
        }
    fft_.run(re_.data(), im_.data(), kN, kN, FftColumns::Direction::Forward);
    for (int k = 0; k < kN * kN; ++k) plane[k] = {re_[k], im_[k]};
}

void CorrelationFilter::inverse_real(const HalfSpectrum& half, Plane& out) {
    for (int h = 0; h < kN * kHalfColumns; ++h) {
        re_[h] = half[h].real();
        im_[h] = half[h].imag();
    }
    fft_.run(re_.data(), im_.data(), kHalfColumns, kHalfColumns, FftColumns::Direction::Inverse);
    // Each row is now the half spectrum of a real line, X(N − u) = conj X(u). Two rows a and b go
    // through one complex inverse as X_a + i·X_b: the real part comes out as a, the imaginary as b.
    // The lone frequencies u = 0 and N/2 of a real line are real: their imaginary parts are dropped.
    // Line y / 2 is laid out as column y / 2 of a block N rows by N / 2 columns.
    constexpr int kLines = kN / 2;
    for (int y = 0; y < kN; y += 2) {
        const int line = y / 2;
        const float* ar = re_.data() + y * kHalfColumns;
        const float* ai = im_.data() + y * kHalfColumns;
        const float* br = ar + kHalfColumns;
        const float* bi = ai + kHalfColumns;
        re_across_[line] = ar[0];
        im_across_[line] = br[0];
        re_across_[kHalf * kLines + line] = ar[kHalf];
        im_across_[kHalf * kLines + line] = br[kHalf];
        for (int u = 1; u < kHalf; ++u) {
            re_across_[u * kLines + line] = ar[u] - bi[u];  // a(u) + i·b(u)
            im_across_[u * kLines + line] = ai[u] + br[u];
            re_across_[(kN - u) * kLines + line] = ar[u] + bi[u];  // conj a(u) + i·conj b(u)
            im_across_[(kN - u) * kLines + line] = br[u] - ai[u];
        }
    }
    fft_.run(re_across_.data(), im_across_.data(), kLines, kLines, FftColumns::Direction::Inverse);
    for (int y = 0; y < kN; y += 2)
        for (int x = 0; x < kN; ++x) {
            out[y * kN + x] = re_across_[x * kLines + y / 2];
            out[(y + 1) * kN + x] = im_across_[x * kLines + y / 2];
        }
}

RAYS_FRAME_KERNEL
void CorrelationFilter::transform_window(const FloatImage& image, const Chroma& chroma, Point centre) {
    window_centre_ = centre;
    const int channels = chroma.present ? kChannels : 1 + kOrientations;
    const int pairs = (channels + 1) / 2;
    window_colour_ = chroma.present;
    window_.fill(image, chroma, centre, window_px_, pairs, pairs_);
    for (int p = 0; p < pairs; ++p) fft2(pairs_[p]);
    // A real plane's spectrum is conjugate-symmetric, so the pair a + ib unpacks as
    // A(k) = (Z(k) + conj Z(−k)) / 2 and B(k) = (Z(k) − conj Z(−k)) / 2i.
    for (int p = 0; p < pairs; ++p) {
        const Spectrum& z = pairs_[p];
        HalfSpectrum& a = features_[2 * p];
        HalfSpectrum& b = features_[std::min(2 * p + 1, kChannels - 1)];  // a lone last channel: b unused
        const bool lone = 2 * p + 1 >= channels;
        for (int v = 0; v < kN; ++v) {
            const Complex* row = z.data() + v * kN;
            const Complex* mirror_row = z.data() + ((kN - v) % kN) * kN;
            for (int u = 0; u < kHalfColumns; ++u) {
                const Complex zk = row[u], zm = std::conj(mirror_row[(kN - u) % kN]);
                const int h = v * kHalfColumns + u;
                a[h] = 0.5f * (zk + zm);
                if (!lone) {
                    const Complex d = zk - zm;
                    b[h] = {0.5f * d.imag(), -0.5f * d.real()};
                }
            }
        }
    }
    if (!chroma.present) {  // no colour: the chroma channels say nothing
        features_[1 + kOrientations].fill({});
        features_[2 + kOrientations].fill({});
    }
}

void CorrelationFilter::learn(const FloatImage& image, const Chroma& chroma, Point centre, double target_px,
                              float rate) {
    const double wanted = std::clamp(kPadding * target_px, kMinWindowPx, kMaxWindowPx);
    const bool fresh = !valid_ || rate >= 1.0f;
    window_px_ = fresh ? wanted : window_px_ + rate * (wanted - window_px_);
    transform_window(image, chroma, centre);
    blend(0.0, 0.0, fresh, rate);
    colour_ = chroma.present;
    valid_ = true;
}

void CorrelationFilter::learn_located(const FloatImage& image, const Chroma& chroma, Point centre, double target_px,
                                      float rate) {
    const double step = window_px_ / kN;
    const double du = (centre.x - window_centre_.x) / step, dv = (centre.y - window_centre_.y) / step;
    if (!valid_ || rate >= 1.0f || std::abs(du) > kN / 4 || std::abs(dv) > kN / 4) {
        learn(image, chroma, centre, target_px, rate);
        return;
    }
    blend(du, dv, false, rate);
    const double wanted = std::clamp(kPadding * target_px, kMinWindowPx, kMaxWindowPx);
    window_px_ += rate * (wanted - window_px_);  // from the next frame on
}

RAYS_FRAME_KERNEL
void CorrelationFilter::blend(double du, double dv, bool fresh, float rate) {
    // The wanted response moved by (du, dv) samples: G(k)·exp(−2πi k·d / N), one ramp per axis.
    for (int k = 0; k < kN; ++k) {
        const int f = k < kHalf ? k : k - kN;  // the signed frequency, so that the ramp is smooth
        ramp_u_[k] = std::polar(1.0f, static_cast<float>(-2.0 * std::numbers::pi * f * du / kN));
        ramp_v_[k] = std::polar(1.0f, static_cast<float>(-2.0 * std::numbers::pi * f * dv / kN));
    }
    // The multi-channel closed form (DSST eq. 5): A_l = G·conj(F_l), B = Σ_l |F_l|², each a running
    // mean over frames at `rate` (MOSSE's update).
    const float keep = fresh ? 0.0f : 1.0f - rate, take = fresh ? 1.0f : rate;
    const int channels = window_colour_ ? kChannels : 1 + kOrientations;
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kHalfColumns; ++u) {
            const int h = v * kHalfColumns + u;
            const Complex g = label_[h] * ramp_u_[u] * ramp_v_[v];
            float energy = 0.0f;
            for (int c = 0; c < channels; ++c) {
                const Complex f = features_[c][h];
                numerator_[c][h] = keep * numerator_[c][h] + take * (g * std::conj(f));
                energy += std::norm(f);
            }
            denominator_[h] = keep * denominator_[h] + take * energy;
        }
    // A mono window's chroma channels are 0: they take nothing, and keep what they had at `keep`.
    for (int c = channels; c < kChannels; ++c)
        for (Complex& a : numerator_[c]) a *= keep;
}

RAYS_FRAME_KERNEL
FilterMatch CorrelationFilter::locate(const FloatImage& image, const Chroma& chroma, Point around) {
    if (!valid_) return {around, 0.0};
    transform_window(image, chroma, around);
    // y = F⁻¹{ Σ_l conj(A_l) Z_l / (B + λ) } (DSST eq. 6), with A_l stored conjugated already.
    const float lambda = kLambda * kN * kN;
    const int channels = colour_ && chroma.present ? kChannels : 1 + kOrientations;
    for (int h = 0; h < kN * kHalfColumns; ++h) response_spectrum_[h] = numerator_[0][h] * features_[0][h];
    for (int c = 1; c < channels; ++c)
        for (int h = 0; h < kN * kHalfColumns; ++h) response_spectrum_[h] += numerator_[c][h] * features_[c][h];
    for (int h = 0; h < kN * kHalfColumns; ++h) response_spectrum_[h] /= denominator_[h] + lambda;
    inverse_real(response_spectrum_, response_);

    int peak = 0;
    for (int k = 1; k < kN * kN; ++k)
        if (response_[k] > response_[peak]) peak = k;
    const int pu = peak % kN, pv = peak / kN;
    // The sidelobe: everything but a small square round the peak (MOSSE's PSR).
    double sum = 0.0, squares = 0.0;
    int n = 0;
    for (int v = 0; v < kN; ++v)
        for (int u = 0; u < kN; ++u) {
            const int du = std::abs((u - pu + kN + kHalf) % kN - kHalf), dv = std::abs((v - pv + kN + kHalf) % kN - kHalf);
            if (du <= kPeakExclusion && dv <= kPeakExclusion) continue;
            const double r = response_[v * kN + u];
            sum += r;
            squares += r * r;
            ++n;
        }
    const double mean = sum / n;
    const double spread = std::sqrt(std::max(0.0, squares / n - mean * mean));
    const double top = response_[peak];
    // Sub-sample peak: a parabola through the peak and its neighbours on each axis (indices wrap).
    auto offset = [&](int before, int after) {
        const double l = response_[before], r = response_[after];
        const double curvature = l - 2.0 * top + r;
        return curvature < 0.0 ? std::clamp(0.5 * (l - r) / curvature, -0.5, 0.5) : 0.0;
    };
    const double ou = offset(pv * kN + (pu + kN - 1) % kN, pv * kN + (pu + 1) % kN);
    const double ov = offset(((pv + kN - 1) % kN) * kN + pu, ((pv + 1) % kN) * kN + pu);
    const double du = (pu < kHalf ? pu : pu - kN) + ou, dv = (pv < kHalf ? pv : pv - kN) + ov;
    const double step = window_px_ / kN;
    const Point at{around.x + du * step, around.y + dv * step};
    const bool in_frame = at.x >= 0.0 && at.y >= 0.0 && at.x <= kFrameSize - 1 && at.y <= kFrameSize - 1;
    return {at, in_frame && spread > 0.0 ? (top - mean) / spread : 0.0};
}

}  // namespace rays
