// SPDX-License-Identifier: Apache-2.0
// RAYS_FRAME_KERNEL marks the frame path's hottest functions. On x86-64 with GCC each is built
// twice, for AVX2 and for any x86-64, and the loader picks the one this machine runs (GCC's
// target_clones: an ifunc resolved once at start-up, an indirect call after that). AVX2 without
// FMA does the same IEEE operations in the same order, only eight at a time where the compiler
// vectorises, so both give the same numbers to the bit (tests/tools/test_frame_kernels.cpp runs
// rays-replay here and under qemu-user emulating a CPU without AVX2, and compares the records).
// Elsewhere (arm64, clang) the mark is nothing: one build, as before.
#pragma once

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define RAYS_FRAME_KERNEL_CLONES 1
#define RAYS_FRAME_KERNEL __attribute__((target_clones("avx2", "default")))
#else
#define RAYS_FRAME_KERNEL_CLONES 0
#define RAYS_FRAME_KERNEL
#endif

namespace rays {

// Which build of the frame kernels this machine runs, for the reports that quote times (raysd's
// ready line, rays-bench): the loader's choice is the CPU's AVX2, asked the same way.
inline const char* frame_kernel_build() {
#if RAYS_FRAME_KERNEL_CLONES
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") ? "x86-64 + AVX2" : "x86-64";
#else
    return "one build";
#endif
}

}  // namespace rays
