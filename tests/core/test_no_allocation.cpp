// The per-frame path allocates nothing: this binary replaces every global operator new/delete and
// malloc/calloc/realloc/free with versions that count, on the thread that calls process(), the
// allocations made while counting is switched on.
#include <catch2/catch.hpp>

#include "core/tracker.hpp"
#include "scenes/scene.hpp"
#include "support/skip.hpp"

#include <memory>

#ifndef RAYS_SANITIZED
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

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

// Counts allocations on this thread for as long as it lives.
class CountingScope {
public:
    CountingScope() {
        g_allocations = 0;
        t_counting = true;
    }
    ~CountingScope() { t_counting = false; }
    CountingScope(const CountingScope&) = delete;
    CountingScope& operator=(const CountingScope&) = delete;
};

long counted_allocations() { return g_allocations.load(); }

}  // namespace

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

namespace {

#ifdef RAYS_SANITIZED
[[noreturn]] void skip_under_asan() {
    rays::test::skip(
        "allocation counting replaces malloc, which AddressSanitizer owns; runs in the Release configuration");
}
#else
void* volatile g_escape = nullptr;  // keeps the compiler from eliding the sanity check's allocations

// A tunable set that differs from the defaults in α, β, K and the ray count, within the capacities.
rays::TrackerTunables changed_tunables(const rays::TrackerTunables& base, const rays::TrackerCapacity& capacity) {
    rays::TrackerTunables t = base;
    t.rays.alpha *= 2.0;
    t.rays.beta *= 4.0;
    t.rays.hypotheses = capacity.max_hypotheses;
    t.rays.count = base.rays.count / 2;
    return t;
}
#endif

}  // namespace

TEST_CASE("the allocation counter counts operator new and malloc on the counting thread", "[no_allocation]") {
#ifdef RAYS_SANITIZED
    skip_under_asan();
#else
    long by_new = 0;
    long by_malloc = 0;
    {
        std::vector<int> grown;
        {
            CountingScope counting;
            grown.resize(64);
            g_escape = grown.data();
        }
        by_new = counted_allocations();
        {
            CountingScope counting;
            g_escape = std::malloc(32);
        }
        by_malloc = counted_allocations();
        std::free(g_escape);
    }
    CHECK(by_new >= 1);
    CHECK(by_malloc == 1);
#endif
}

TEST_CASE("Tracker::process and set_tunables allocate nothing while tracking a scene", "[no_allocation]") {
#ifdef RAYS_SANITIZED
    skip_under_asan();
#else
    constexpr int kFrames = 200;
    const rays::TrackerConfig config;
    const rays::SteadyClock clock;
    rays::Tracker tracker(config, clock);
    const rays::TrackerTunables changed = changed_tunables(config.tunables, config.capacity);
    REQUIRE(changed.rays.count >= config.tunables.rays.centroid_rays);

    auto scene = rays::scenes::make_scene("clutter");
    REQUIRE(scene != nullptr);
    REQUIRE(scene->frame_count() >= kFrames);
    std::vector<rays::GreyImage> frames(kFrames);
    {
        const auto rendered = std::make_unique<rays::scenes::SceneFrame>();
        for (int i = 0; i < kFrames; ++i) {
            scene->render(i, *rendered);
            frames[static_cast<std::size_t>(i)] = rendered->image;
        }
    }

    const rays::TimePoint deadline = clock.now() + std::chrono::hours(1);
    int tracking = 0;
    bool tunables_applied = false;
    long allocations = 0;
    {
        CountingScope counting;
        for (int i = 0; i < kFrames; ++i) {
            if (i == kFrames / 2) tunables_applied = tracker.set_tunables(changed);
            if (tracker.process(frames[static_cast<std::size_t>(i)], deadline).state == rays::TrackState::Tracking) ++tracking;
        }
        allocations = counted_allocations();
    }
    CHECK(tunables_applied);
    CHECK(tracker.tunables().rays.count == changed.rays.count);
    CHECK(allocations == 0);
    CHECK(tracking >= 100);
#endif
}
