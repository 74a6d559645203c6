// SPDX-License-Identifier: Apache-2.0
// Speeds in px/frame, sizes in px, grey levels 0–255. Every target moves from frame 0, since the
// tracker finds it in frame differences.
#include "scenes/scripts.hpp"

#include <cmath>
#include <numbers>

#include "scenes/paths.hpp"

namespace rays::scenes::scripts {
namespace {

constexpr double kPi = std::numbers::pi;

// Leg phase of a walker after `distance_px`: one gait cycle (two steps) per 0.8 body heights.
double gait_phase(double distance_px, double height_px) { return 2 * kPi * distance_px / (0.8 * height_px); }

}  // namespace

void disc(int t, Canvas& c, Random& r) {
    c.fill(50);
    c.paint(Disc{64 + 28 * std::cos(2 * kPi * t / 120.0), 64 + 28 * std::sin(2 * kPi * t / 120.0), 14}, 200, true);
    c.noise(3, r);
}

// Moves right for frames 0–59, is gone for frames 60–99, then circles from a far place.
void vanish(int t, Canvas& c, Random& r) {
    c.fill(50);
    if (t < 60) c.paint(Disc{24 + 1.4 * t, 40, 13}, 200, true);
    if (t >= 100) {
        const Point p = Loop{64, 80, 24, 24, 0, 0.0625, kPi}.at(t - 100);
        c.paint(Disc{p.x, p.y, 13}, 200, true);
    }
    c.noise(3, r);
}

// A 14×10 ellipse heading along a loop at 2.1–2.9 px/frame.
void clutter(int t, Canvas& c, Random& r) {
    c.texture(110, 20, 24, 3);
    c.clutter(26, 30, 170, 33);
    const Loop path{64, 64, 38, 28, 0.2, 0.075, 0};
    const Point p = path.at(t);
    c.paint(Ellipse{p.x, p.y, 14, 10, path.heading(t)}, 205, true);
    c.noise(4, r);
}

// Outer radius 22, inner 10, turning 0.03 rad/frame, drifting at 1.1–1.5 px/frame.
void star(int t, Canvas& c, Random& r) {
    c.texture(100, 25, 16, 4);
    const Point p = Loop{64, 64, 30, 22, 0, 0.05, 0.5}.at(t);
    c.paint(Star{p.x, p.y, 22, 10, 5, 0.03 * t}, 190, true);
    c.noise(4, r);
}

// A 52 px walker pacing at 1.5 px/frame between x = 24 and 104, past a dark pole at x = 70–74.
void walker_pole(int t, Canvas& c, Random& r) {
    constexpr double height = 52;
    c.texture(150, 15, 20, 5);
    c.rect(70, -1, 74, 128, 60);
    const double walked = 10 + 1.5 * t;
    c.paint(Walker{bounce(24, 104, walked), 66, height, gait_phase(walked, height)}, 55, true);
    c.noise(4, r);
}

// The target is 18 grey levels above its surround; rectangles and lines 55–60 levels off the
// surround pass within a few px of its loop (1.4–1.9 px/frame) without touching it.
void weak_contrast(int t, Canvas& c, Random& r) {
    c.texture(100, 6, 20, 6);
    c.rect(52, 55, 76, 69, 155);  // inside the loop
    c.rect(0, 0, 34, 30, 45);
    c.rect(94, 0, 128, 30, 160);
    c.rect(0, 94, 34, 128, 160);
    c.rect(94, 94, 128, 128, 45);
    c.line(0, 62, 14, 62, 2, 160);
    c.line(114, 62, 128, 62, 2, 45);
    const Point p = Loop{64, 62, 32, 24, 0, 0.06, 1.0}.at(t);
    c.paint(Ellipse{p.x, p.y, 13, 11}, 118, true);
    c.noise(3, r);
}

// The shadow (0.45 × the light, target included) lies where 0.8x − 0.6y > 20; the blob's loop
// (1.1–2.5 px/frame) runs across that border, starting in the sun.
void shadow(int t, Canvas& c, Random& r) {
    c.texture(150, 15, 20, 7);
    const Point p = Loop{64, 52, 36, 16, -0.6435, 0.07, kPi + 0.5}.at(t);
    c.paint(Ellipse{p.x, p.y, 12, 10}, 215, true);
    c.multiply_half_plane(0.8, -0.6, 20, 0.45);
    c.noise(4, r);
}

// A 13×10 ellipse on a flat loop (1.2–2.6 px/frame) that passes behind an 8 px bar six times.
void occluder(int t, Canvas& c, Random& r) {
    c.texture(100, 15, 20, 8);
    const Point p = Loop{64, 64, 44, 20, 0, 0.06, kPi + 0.6}.at(t);
    c.paint(Ellipse{p.x, p.y, 13, 10}, 195, true);
    c.occlude(60, -1, 68, 128, 35);
    c.noise(4, r);
}

// Back and forth between x = 20 and 108 (the ellipse stays inside), speed from ramp_distance().
void speed_ramp(int t, Canvas& c, Random& r) {
    c.texture(90, 15, 20, 9);
    c.paint(Ellipse{bounce(20, 108, ramp_distance(t)), 64, 11, 9}, 200, true);
    c.noise(4, r);
}

// 60 grey levels of contrast, blurred (σ 1.5 px) and then under σ 20 noise; 1.3–1.8 px/frame.
void noise_blur(int t, Canvas& c, Random& r) {
    c.texture(100, 10, 24, 10);
    const Point p = Loop{64, 64, 32, 24, 0, 0.055, 0}.at(t);
    c.paint(Ellipse{p.x, p.y, 15, 12}, 160, true);
    c.gaussian_blur(1.5);
    c.noise(20, r);
}

// A walker coming towards the camera: its height grows as 1/distance from 25 to 75 px over the 300
// frames, while it zigzags sideways at 1.2 px/frame and its feet come lower in the frame.
void approach(int t, Canvas& c, Random& r) {
    c.texture(150, 15, 20, 11);
    const double height = 25 / (1 - (2.0 / 3.0) * t / 299.0);
    c.paint(Walker{bounce(36, 92, 8 + 1.2 * t), 58 + 0.1 * height, height, 0.25 * t}, 55, true);
    c.noise(4, r);
}

// A 13×10 ellipse 12 grey levels below the mean of a busy texture (±25 over 10 px cells) that is
// darker than the target in places: its rim is weaker than the texture's own edges almost
// everywhere. Along a loop at 1.1–1.8 px/frame.
void camouflage(int t, Canvas& c, Random& r) {
    c.texture(112, 25, 10, 12);
    const Point p = Loop{64, 64, 30, 24, 0, 0.055, 0.3}.at(t);
    c.paint(Ellipse{p.x, p.y, 13, 10, 0.4}, 100, true);
    c.noise(3, r);
}

}  // namespace rays::scenes::scripts
