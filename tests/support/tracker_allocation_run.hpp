// SPDX-License-Identifier: Apache-2.0
// The no-allocation run both contour trackers are held to: a generated scene's frames are rendered
// first, then the tracker processes them with allocation counting on (thread_allocation_counter.hpp),
// gets `changed` tunables half-way through and, three quarters through, is released and started in
// the box round the target. With `colour`, each frame comes with colours drawn from its mask (the
// target red, the background green), so that the tracker's colour model learns and looks too.
#pragma once
#include <string_view>

#include "core/contour_tracker.hpp"

namespace rays::test {

struct TrackerAllocationRun {
    int tracking = 0;               // frames that ended in the tracking state
    bool tunables_applied = false;  // set_tunables(changed) accepted them
    bool box_tracked = false;       // start_in(the target's box) was accepted and its frame ended tracking
    long allocations = 0;           // on this thread while processing
};

TrackerAllocationRun count_tracker_allocations(ContourTracker& tracker, std::string_view scene, int frames,
                                               const TrackerTunables& changed, bool colour = false);

}  // namespace rays::test
