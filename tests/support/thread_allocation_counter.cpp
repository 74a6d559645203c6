// SPDX-License-Identifier: Apache-2.0
// Replaces every global allocation function of the test binary it is linked into (see the header).
#ifndef RAYS_SANITIZED
#include "support/thread_allocation_counter.hpp"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

// glibc's own allocator, under the names it exports beside malloc.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* block, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* block);
}

namespace {

thread_local bool t_counting = false;  // set only on the thread under test
std::atomic<long> g_allocations{0};

void note_allocation() noexcept {
    if (t_counting) g_allocations.fetch_add(1, std::memory_order_relaxed);
}

void* new_block(std::size_t size) {
    note_allocation();
    if (void* p = __libc_malloc(size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* new_aligned_block(std::size_t size, std::align_val_t alignment) {
    note_allocation();
    if (void* p = __libc_memalign(static_cast<std::size_t>(alignment), size == 0 ? 1 : size)) return p;
    throw std::bad_alloc();
}

void* new_block_or_null(std::size_t size) noexcept {
    note_allocation();
    return __libc_malloc(size == 0 ? 1 : size);
}

void* new_aligned_block_or_null(std::size_t size, std::align_val_t alignment) noexcept {
    note_allocation();
    return __libc_memalign(static_cast<std::size_t>(alignment), size == 0 ? 1 : size);
}

}  // namespace

void rays::test::start_counting_allocations() {
    g_allocations = 0;
    t_counting = true;
}
void rays::test::stop_counting_allocations() { t_counting = false; }
long rays::test::counted_allocations() { return g_allocations.load(); }

extern "C" {
void* malloc(std::size_t size) noexcept {
    note_allocation();
    return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
    note_allocation();
    return __libc_calloc(count, size);
}
void* realloc(void* block, std::size_t size) noexcept {
    note_allocation();
    return __libc_realloc(block, size);
}
void free(void* block) noexcept { __libc_free(block); }
}

void* operator new(std::size_t size) { return new_block(size); }
void* operator new[](std::size_t size) { return new_block(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return new_block_or_null(size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return new_block_or_null(size); }
void* operator new(std::size_t size, std::align_val_t a) { return new_aligned_block(size, a); }
void* operator new[](std::size_t size, std::align_val_t a) { return new_aligned_block(size, a); }
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
    return new_aligned_block_or_null(size, a);
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
    return new_aligned_block_or_null(size, a);
}
void operator delete(void* p) noexcept { __libc_free(p); }
void operator delete[](void* p) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
#endif  // RAYS_SANITIZED
