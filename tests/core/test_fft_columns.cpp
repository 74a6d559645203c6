// SPDX-License-Identifier: Apache-2.0
// FftColumns against the DFT's definition, summed directly in double precision.
#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "core/fft_columns.hpp"

namespace {

using rays::FftColumns;
constexpr int kN = FftColumns::kPoints;

// X(k) = Σ_n x(n)·e^(sign·2πi·nk/N) of column c of a block with rows `stride` apart.
std::complex<double> direct(const std::vector<float>& re, const std::vector<float>& im, int c, int stride, int k,
                            double sign) {
    std::complex<double> sum{};
    for (int n = 0; n < kN; ++n)
        sum += std::complex<double>(re[n * stride + c], im[n * stride + c]) *
               std::polar(1.0, sign * 2.0 * std::numbers::pi * n * k / kN);
    return sum;
}

}  // namespace

TEST_CASE("FftColumns is the DFT of every column, forward and inverse", "[fft]") {
    std::mt19937 rng(5u);
    std::uniform_real_distribution<float> value(-1.0f, 1.0f);
    const FftColumns fft;
    for (const int columns : {1, 16, 17, 32}) {  // the filter's blocks: 17 half-spectrum columns, 16 packed lines
        const int stride = columns + 3;          // rows further apart than the columns used
        std::vector<float> re(static_cast<std::size_t>(kN * stride)), im(re.size());
        for (std::size_t i = 0; i < re.size(); ++i) re[i] = value(rng), im[i] = value(rng);
        for (const auto direction : {FftColumns::Direction::Forward, FftColumns::Direction::Inverse}) {
            std::vector<float> out_re = re, out_im = im;
            fft.run(out_re.data(), out_im.data(), columns, stride, direction);
            const double sign = direction == FftColumns::Direction::Forward ? -1.0 : 1.0;
            for (int c = 0; c < columns; ++c)
                for (int k = 0; k < kN; ++k) {
                    const std::complex<double> want = direct(re, im, c, stride, k, sign);
                    REQUIRE(out_re[k * stride + c] == Approx(want.real()).margin(1e-4));
                    REQUIRE(out_im[k * stride + c] == Approx(want.imag()).margin(1e-4));
                }
            // The padding beyond the columns is not touched.
            for (int n = 0; n < kN; ++n)
                for (int c = columns; c < stride; ++c) REQUIRE(out_re[n * stride + c] == re[n * stride + c]);
        }
    }
}

TEST_CASE("FftColumns forward then inverse gives the block back, N times", "[fft]") {
    std::mt19937 rng(6u);
    std::uniform_real_distribution<float> value(-100.0f, 100.0f);
    const FftColumns fft;
    std::vector<float> re(kN * kN), im(kN * kN);
    for (std::size_t i = 0; i < re.size(); ++i) re[i] = value(rng), im[i] = value(rng);
    std::vector<float> r = re, m = im;
    fft.run(r.data(), m.data(), kN, kN, FftColumns::Direction::Forward);
    fft.run(r.data(), m.data(), kN, kN, FftColumns::Direction::Inverse);
    for (std::size_t i = 0; i < re.size(); ++i) {
        REQUIRE(r[i] / kN == Approx(re[i]).margin(1e-3));
        REQUIRE(m[i] / kN == Approx(im[i]).margin(1e-3));
    }
}
