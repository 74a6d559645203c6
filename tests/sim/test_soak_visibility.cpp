// SPDX-License-Identifier: Apache-2.0
// The soak scenario over its 30 minutes: the target passes behind the poles now and then but is
// never more than about 40 % hidden.
#include <catch2/catch.hpp>

#include "sim_rig.hpp"
#include "support/emulator.hpp"

using namespace rays;
using namespace rays::sim;

TEST_CASE("soak: with the unit on the target it is always in view and never more than 40 % hidden") {
    rays::test::skip_under_emulation("the whole soak scenario rendered; the short rendering cases run on arm64");
    for (const char* name : {"soak", "soak-clutter"}) {
        INFO(name);
        const auto camera = test::named_camera(name);
        REQUIRE(camera);
        const Path& path = *camera->scenario().targets[camera->scenario().primary].path;
        auto view = std::make_unique<SimView>();
        double least_visible = 1.0;
        int partly_hidden = 0;
        for (double t = 0; t <= 1800.0; t += 0.5) {
            const PathPoint at = path.at(t);
            camera->render(t, at.position.azimuth, at.position.elevation, *view);
            if (!view->truth.in_view || view->truth.visible_fraction < 0.6) {
                INFO("t = " << t << ", visible " << view->truth.visible_fraction);
                CHECK(view->truth.in_view);
                CHECK(view->truth.visible_fraction >= 0.6);
            }
            least_visible = std::min(least_visible, view->truth.visible_fraction);
            partly_hidden += view->truth.visible_fraction < 0.97;
        }
        CHECK(least_visible < 0.85);   // the poles do pass in front
        CHECK(partly_hidden > 50);
    }
}
