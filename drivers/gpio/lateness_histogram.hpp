// SPDX-License-Identifier: Apache-2.0
// How late the pulse thread's edges come: counts in power-of-two buckets of microseconds after the
// due time (bucket 0: under 1 µs, bucket k: [2^(k-1), 2^k) µs, the last open-ended). Fixed memory, so
// the pulse thread can keep it for its whole life; quantiles are a bucket's upper bound.
#pragma once
#include <array>
#include <cmath>
#include <cstddef>

namespace rays::gpio {

struct LatenessHistogram {
    static constexpr std::size_t kBuckets = 18;  // up to 65.536 ms, then open-ended
    std::array<long, kBuckets> counts{};

    void add(double late_us) {
        std::size_t bucket = 0;
        for (double bound = 1.0; bucket + 1 < kBuckets && late_us >= bound; bound *= 2.0) ++bucket;
        ++counts[bucket];
    }
    long total() const {
        long sum = 0;
        for (long count : counts) sum += count;
        return sum;
    }
    static double upper_us(std::size_t bucket) { return std::ldexp(1.0, static_cast<int>(bucket)); }
    // The upper bound of the bucket holding quantile q (0..1); 0 when empty, infinity in the last bucket.
    double quantile_us(double q) const {
        const long n = total();
        if (n == 0) return 0.0;
        long seen = 0;
        for (std::size_t b = 0; b < kBuckets; ++b) {
            seen += counts[b];
            if (static_cast<double>(seen) >= q * static_cast<double>(n))
                return b + 1 < kBuckets ? upper_us(b) : INFINITY;
        }
        return INFINITY;
    }
};

}  // namespace rays::gpio
