#include "support/tracker_allocation_run.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <memory>
#include <vector>

#include "scenes/scene.hpp"
#include "support/thread_allocation_counter.hpp"

// Like the counter itself, only where the allocator can be replaced (not under AddressSanitizer).
#ifndef RAYS_SANITIZED
namespace rays::test {

TrackerAllocationRun count_tracker_allocations(ContourTracker& tracker, std::string_view scene_name, int frames,
                                               const TrackerTunables& changed) {
    auto scene = scenes::make_scene(scene_name);
    REQUIRE(scene != nullptr);
    REQUIRE(scene->frame_count() >= frames);
    std::vector<GreyImage> images(static_cast<std::size_t>(frames));
    {
        const auto rendered = std::make_unique<scenes::SceneFrame>();
        for (int i = 0; i < frames; ++i) {
            scene->render(i, *rendered);
            images[static_cast<std::size_t>(i)] = rendered->image;
        }
    }

    const TimePoint deadline = MonoClock::now() + std::chrono::hours(1);
    TrackerAllocationRun run;
    {
        CountingScope counting;
        for (int i = 0; i < frames; ++i) {
            if (i == frames / 2) run.tunables_applied = tracker.set_tunables(changed);
            if (tracker.process(images[static_cast<std::size_t>(i)], deadline).state == TrackState::Tracking)
                ++run.tracking;
        }
        run.allocations = counted_allocations();
    }
    return run;
}

}  // namespace rays::test
#endif
