// SPDX-License-Identifier: Apache-2.0
// The scenes' scripts: each draws frame t of one scene (background, target, disturbances) onto a
// fresh canvas, from fixed parameters and with `random` seeded for that scene and frame.
#pragma once
#include "scenes/render.hpp"

namespace rays::scenes::scripts {

using Script = void (*)(int t, Canvas& canvas, Random& random);

void disc(int t, Canvas& c, Random& r);
void vanish(int t, Canvas& c, Random& r);
void clutter(int t, Canvas& c, Random& r);
void star(int t, Canvas& c, Random& r);
void walker_pole(int t, Canvas& c, Random& r);
void weak_contrast(int t, Canvas& c, Random& r);
void shadow(int t, Canvas& c, Random& r);
void occluder(int t, Canvas& c, Random& r);
void speed_ramp(int t, Canvas& c, Random& r);
void noise_blur(int t, Canvas& c, Random& r);
void approach(int t, Canvas& c, Random& r);
void camouflage(int t, Canvas& c, Random& r);

}  // namespace rays::scenes::scripts
