// SPDX-License-Identifier: Apache-2.0
#include "support/tracker_allocation_run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "scenes/scene.hpp"
#include "support/thread_allocation_counter.hpp"

// Like the counter itself, only where the allocator can be replaced (not under AddressSanitizer).
#ifndef RAYS_SANITIZED
namespace rays::test {
namespace {

Box mask_box(const GreyImage& mask) {
    int x0 = kFrameSize, y0 = kFrameSize, x1 = -1, y1 = -1;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x)
            if (mask.at(x, y) > 127) {
                x0 = std::min(x0, x);
                y0 = std::min(y0, y);
                x1 = std::max(x1, x);
                y1 = std::max(y1, y);
            }
    REQUIRE(x1 >= x0);
    return {static_cast<double>(x0), static_cast<double>(y0), static_cast<double>(x1 - x0 + 1), static_cast<double>(y1 - y0 + 1)};
}

// Red where the mask is set, green elsewhere, over each chroma pixel's 2×2 block.
Chroma mask_colours(const GreyImage& mask) {
    Chroma chroma;
    chroma.present = true;
    for (int j = 0; j < kChromaSize; ++j)
        for (int i = 0; i < kChromaSize; ++i) {
            const bool target = mask.at(2 * i, 2 * j) > 127;
            chroma.u[static_cast<std::size_t>(j * kChromaSize + i)] = target ? 100 : 90;
            chroma.v[static_cast<std::size_t>(j * kChromaSize + i)] = target ? 190 : 80;
        }
    return chroma;
}

}  // namespace

TrackerAllocationRun count_tracker_allocations(ContourTracker& tracker, std::string_view scene_name, int frames,
                                               const TrackerTunables& changed, bool colour) {
    auto scene = scenes::make_scene(scene_name);
    REQUIRE(scene != nullptr);
    REQUIRE(scene->frame_count() >= frames);
    std::vector<GreyImage> images(static_cast<std::size_t>(frames));
    std::vector<Chroma> colours(colour ? static_cast<std::size_t>(frames) : 0);
    const int box_frame = frames * 3 / 4;
    Box box;  // the target's extent in box_frame: its mask's bounding box
    {
        const auto rendered = std::make_unique<scenes::SceneFrame>();
        for (int i = 0; i < frames; ++i) {
            scene->render(i, *rendered);
            images[static_cast<std::size_t>(i)] = rendered->image;
            if (colour) colours[static_cast<std::size_t>(i)] = mask_colours(rendered->mask);
            if (i == box_frame) box = mask_box(rendered->mask);
        }
    }

    const TimePoint deadline = MonoClock::now() + std::chrono::hours(1);
    TrackerAllocationRun run;
    {
        CountingScope counting;
        for (int i = 0; i < frames; ++i) {
            if (i == frames / 2) run.tunables_applied = tracker.set_tunables(changed);
            if (i == box_frame) {
                tracker.release();
                run.box_tracked = tracker.start_in(box);
            }
            const Chroma& chroma = colour ? colours[static_cast<std::size_t>(i)] : kNoChroma;
            const TrackState state = tracker.process(images[static_cast<std::size_t>(i)], chroma, deadline).state;
            if (state == TrackState::Tracking) ++run.tracking;
            if (i == box_frame) run.box_tracked = run.box_tracked && state == TrackState::Tracking;
        }
        run.allocations = counted_allocations();
    }
    return run;
}

}  // namespace rays::test
#endif
