// SPDX-License-Identifier: Apache-2.0
// The per-frame path allocates nothing: allocations on the thread that calls process() are counted
// (support/thread_allocation_counter.hpp) while counting is switched on.
#include <catch2/catch.hpp>

#include "core/tracker.hpp"
#include "support/camouflaged_target_scene.hpp"
#include "support/panning_scene.hpp"
#include "support/skip.hpp"
#include "support/thread_allocation_counter.hpp"
#include "support/tracker_allocation_run.hpp"

#include <cmath>
#include <memory>
#include <vector>


using rays::test::counted_allocations;
using rays::test::CountingScope;

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

TEST_CASE("Tracker::process, set_tunables and a box start allocate nothing while tracking a scene", "[no_allocation]") {
#ifdef RAYS_SANITIZED
    skip_under_asan();
#else
    constexpr int kFrames = 200;
    const rays::TrackerConfig config;
    const rays::SteadyClock clock;
    rays::Tracker tracker(config, clock);
    const rays::TrackerTunables changed = changed_tunables(config.tunables, config.capacity);
    REQUIRE(changed.rays.count >= config.tunables.rays.centroid_rays);
    // Grey frames, and the same frames with colour (the colour model's learning and looking).
    const bool colour = GENERATE(false, true);
    INFO((colour ? "with colour" : "grey"));

    const rays::test::TrackerAllocationRun run =
        rays::test::count_tracker_allocations(tracker, "clutter", kFrames, changed, colour);
    CHECK(run.tunables_applied);
    CHECK(run.box_tracked);
    CHECK(tracker.tunables().rays.count == changed.rays.count);
    CHECK(run.allocations == 0);
    CHECK(run.tracking >= 100);
    CHECK(tracker.appearance().valid() == colour);
#endif
}

TEST_CASE("Tracker::process allocates nothing while the motion layers learn and are read (colour, panning view)",
          "[no_allocation]") {
#ifdef RAYS_SANITIZED
    skip_under_asan();
#else
    constexpr int kFrames = 40;
    const rays::TrackerConfig config;
    const rays::SteadyClock clock;
    rays::Tracker tracker(config, clock);
    // Drawn before counting: the scene's frames are the caller's, not the tracker's.
    std::vector<std::unique_ptr<rays::test::CamouflagedTargetScene>> frames;
    for (int f = 0; f < kFrames; ++f) {
        frames.push_back(std::make_unique<rays::test::CamouflagedTargetScene>());
        frames.back()->draw(f);
    }
    tracker.start_at(frames.front()->centre(0));
    long allocations = 0;
    int tracking = 0;
    double overlap = 0.0;  // over the last half of the frames
    for (int f = 0; f < kFrames; ++f) {
        const auto& scene = *frames[static_cast<std::size_t>(f)];
        {
            CountingScope counting;
            tracking += tracker.process(scene.image, scene.chroma, rays::TimePoint::max()).state == rays::TrackState::Tracking;
        }
        allocations += counted_allocations();
        if (f >= kFrames / 2) overlap += rays::test::contour_mask_iou(tracker.contour(), scene.mask) / (kFrames / 2);
    }
    CHECK(allocations == 0);
    // Tracked through, round the target: the layers were learned and read (without them the contour
    // wanders over the texture: test_motion_layers.cpp).
    CHECK(tracking == kFrames);
    CHECK(overlap > 0.8);
#endif
}

TEST_CASE("Tracker::process allocates nothing while a grey source's motion layers learn and are read (the unit turning)",
          "[no_allocation]") {
#ifdef RAYS_SANITIZED
    skip_under_asan();
#else
    // The scene of "Tracker on a grey source cuts off a block beside the target ...": the layers'
    // background is what keeps the contour off the block sliding past.
    rays::test::PanningScene run;
    run.block = true;
    run.turning = true;
    run.tracker.start_at({64.0, 64.0});
    long allocations = 0;
    int tracking = 0;
    double overlap = 0.0;  // while the block touches the target, frames 5 … 39
    for (int i = 0; i < 40; ++i) {
        {
            CountingScope counting;
            tracking += run.step({1.0 * i, 0.0}, {64.0, 64.0}) == rays::TrackState::Tracking;
        }
        allocations += counted_allocations();
        if (i >= 5) overlap += run.contour_iou() / 35.0;
    }
    CHECK(allocations == 0);
    CHECK(tracking == 40);
    CHECK(overlap > 0.72);
#endif
}
