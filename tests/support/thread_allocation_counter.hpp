// SPDX-License-Identifier: Apache-2.0
// Counts heap allocations (operator new and malloc/calloc/realloc) made on one thread while
// counting is on, to prove a path allocates nothing. Linking thread_allocation_counter.cpp replaces
// the global allocator of that test binary. Not available under AddressSanitizer, which owns malloc.
#pragma once

namespace rays::test {

#ifdef RAYS_SANITIZED
constexpr bool kAllocationCounting = false;
#else
constexpr bool kAllocationCounting = true;
#endif

// Resets the count and counts allocations on the calling thread from now on.
void start_counting_allocations();
void stop_counting_allocations();  // on the thread that started
long counted_allocations();

// Counts on the thread that creates it for as long as it lives.
class CountingScope {
public:
    CountingScope() { start_counting_allocations(); }
    ~CountingScope() { stop_counting_allocations(); }
    CountingScope(const CountingScope&) = delete;
    CountingScope& operator=(const CountingScope&) = delete;
};

}  // namespace rays::test
