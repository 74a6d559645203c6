// SPDX-License-Identifier: Apache-2.0
#include "sim/sim_camera.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "common/angles.hpp"
#include "scenes/render.hpp"
#include "sim/value_noise.hpp"

namespace rays::sim {
namespace {

constexpr double kWorldPxPerRad = kWorldPxPerDeg * kDegPerRad;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::array kSubOffsets{-0.375, -0.125, 0.125, 0.375};  // 4×4 samples across a pixel
constexpr double kSamplesPerPixel = kSubOffsets.size() * kSubOffsets.size();

// A viewing direction D (not normalised) against a target's tangent plane: D·east, D·down and
// D·centre. D falls on the plane at (K·east/depth, K·down/depth) world px, K = kWorldPxPerRad.
struct PlaneDots {
    double east, down, depth;
};

// A target as placed in one frame: its outline, the frame of its tangent plane and how the plane
// dot products change along a sub-pixel step.
struct PlacedTarget {
    PlanarShape shape;
    scenes::Box bounds;  // the outline's box grown by a pixel's footprint, world px
    Eigen::Vector3d centre, east, down;
    PlaneDots step_x, step_y;
    double cos_reach;  // only directions closer to the centre than this cosine can touch the outline
    double grey, texture_amplitude, texture_cell_world_px;
    std::uint64_t texture_seed;
    bool primary;

    PlaneDots dots(const Eigen::Vector3d& d) const { return {d.dot(east), d.dot(down), d.dot(centre)}; }
};

// Where a frame looks: its optical axis, how far from it the frame reaches, and one pixel's step
// along x and y of the rays (world frame, rays scaled to z = 1 in the camera's).
struct FrameGeometry {
    Eigen::Vector3d axis, step_x, step_y;
    double view_reach_rad, pixel_reach_rad;
};

// The target placed at time t, or nothing when it is away or too far off the optical axis to show.
std::optional<PlacedTarget> place(const Target& target, double t_s, const FrameGeometry& frame,
                                  std::uint64_t texture_seed, bool primary) {
    if (!target.presence.at(t_s)) return std::nullopt;
    const PathPoint at = target.path->at(t_s);
    PlacedTarget p;
    p.shape = planar_shape(target.shape, t_s, at);
    const scenes::Box box = outline_box(p.shape);
    const double reach_rad = std::atan(std::hypot(std::max(-box.x0, box.x1), std::max(-box.y0, box.y1)) / kWorldPxPerRad) +
                             frame.pixel_reach_rad;
    p.centre = control::direction_of(at.position);
    if (p.centre.dot(frame.axis) < std::cos(std::min(std::numbers::pi, frame.view_reach_rad + reach_rad)))
        return std::nullopt;
    // A pixel's footprint on the plane, which stretches by up to 1/cos² of the angle off its centre.
    const double margin = kWorldPxPerRad * frame.pixel_reach_rad / (std::cos(reach_rad) * std::cos(reach_rad));
    p.bounds = {box.x0 - margin, box.y0 - margin, box.x1 + margin, box.y1 + margin};
    const double az = at.position.azimuth, el = at.position.elevation;
    p.east = {std::cos(az), 0.0, -std::sin(az)};
    p.down = {std::sin(el) * std::sin(az), std::cos(el), std::sin(el) * std::cos(az)};
    p.step_x = p.dots(frame.step_x);
    p.step_y = p.dots(frame.step_y);
    p.cos_reach = std::cos(reach_rad);
    p.grey = target.grey;
    p.texture_amplitude = target.texture_amplitude;
    p.texture_cell_world_px = target.texture_cell_deg * kWorldPxPerDeg;
    p.texture_seed = texture_seed;
    p.primary = primary;
    return p;
}

// The share of the 4×4 samples of the pixel whose centre ray has `at` inside the outline.
template <class Shape>
double outline_coverage(const Shape& shape, const PlacedTarget& p, const PlaneDots& at) {
    int inside = 0;
    for (double sy : kSubOffsets)
        for (double sx : kSubOffsets) {
            const double scale = kWorldPxPerRad / (at.depth + sx * p.step_x.depth + sy * p.step_y.depth);
            inside += shape.inside((at.east + sx * p.step_x.east + sy * p.step_y.east) * scale,
                                   (at.down + sx * p.step_x.down + sy * p.step_y.down) * scale);
        }
    return inside / kSamplesPerPixel;
}

// The target's grey at a point (u, v) of its plane: its own, with its texture where it has one.
double target_grey(const PlacedTarget& p, double u, double v) {
    if (p.texture_amplitude == 0) return p.grey;
    const double n = fractal_noise(u / p.texture_cell_world_px, v / p.texture_cell_world_px, p.texture_seed, 2);
    return p.grey + p.texture_amplitude * (2 * n - 1);
}

// Sensor noise of unit variance: the Irwin–Hall sum of four 16-bit uniforms from one draw, close
// to Gaussian and far cheaper than Box–Muller for 16384 pixels.
double unit_noise(scenes::Random& random) {
    const std::uint64_t bits = random.next();
    double sum = 0;
    for (int k = 0; k < 4; ++k) sum += (static_cast<double>((bits >> (16 * k)) & 0xFFFFu) + 0.5) / 65536.0;
    return (sum - 2.0) * std::sqrt(3.0);
}

std::uint64_t frame_seed(std::uint64_t scenario_seed, double t_s) {
    scenes::Random mix(scenario_seed * 0x9E3779B97F4A7C15ull ^ std::bit_cast<std::uint64_t>(t_s));
    return mix.next();
}

// What SimTruth says about the primary target's centre, from where its path puts it at t.
void describe_centre(const PathPoint& at, const control::CameraModel& camera, const Eigen::Matrix3d& camera_to_world,
                     SimTruth& truth) {
    truth.target = {control::angle_difference(at.position.azimuth, 0.0), at.position.elevation};
    truth.speed_deg_s = angular_speed(at) * kDegPerRad;
    const double az = at.position.azimuth, el = at.position.elevation;
    const Eigen::Vector3d velocity =
        at.azimuth_rate * Eigen::Vector3d(std::cos(el) * std::cos(az), 0.0, -std::cos(el) * std::sin(az)) +
        at.elevation_rate * Eigen::Vector3d(-std::sin(el) * std::sin(az), -std::cos(el), -std::sin(el) * std::cos(az));
    const Eigen::Vector3d d = camera_to_world.transpose() * control::direction_of(at.position);
    const Eigen::Vector3d v = camera_to_world.transpose() * velocity;
    const std::optional<Point> pixel = camera.project(d);
    if (!pixel) {
        truth.centre_px = {kNaN, kNaN};
        truth.speed_px_per_s = kNaN;
        return;
    }
    truth.centre_px = *pixel;
    const control::Intrinsics& k = camera.intrinsics();
    const double x_rate = k.fx * (v.x() * d.z() - d.x() * v.z()) / (d.z() * d.z());
    const double y_rate = k.fy * (v.y() * d.z() - d.y() * v.z()) / (d.z() * d.z());
    truth.speed_px_per_s = std::hypot(x_rate, y_rate);
}

}  // namespace

SimCamera::SimCamera(Scenario scenario, const control::CameraModel& camera, Panorama panorama)
    : scenario_(std::move(scenario)),
      camera_(camera),
      panorama_(std::move(panorama)),
      rays_(kFramePixels),
      pixel_reach_rad_(1.0 / std::min(camera.intrinsics().fx, camera.intrinsics().fy)),
      view_reach_rad_(0) {
    if (scenario_.targets.empty() || scenario_.targets.size() > kMaxTargets)
        throw std::invalid_argument("a simulated scenario needs 1 to 8 targets");
    if (scenario_.occluders.size() > kMaxOccluders)
        throw std::invalid_argument("a simulated scenario has at most 32 occluders");
    if (scenario_.primary >= scenario_.targets.size())
        throw std::invalid_argument("the scenario's primary target is not one of its targets");
    for (const Target& target : scenario_.targets)
        if (!target.path) throw std::invalid_argument("a simulated target has no path");
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            const Eigen::Vector3d r = camera_.ray({double(x), double(y)});
            rays_[static_cast<std::size_t>(y * kFrameSize + x)] = r / r.z();
        }
    for (double x : {-0.5, kFrameSize - 0.5})
        for (double y : {-0.5, kFrameSize - 0.5})
            view_reach_rad_ = std::max(view_reach_rad_, std::acos(camera_.ray({x, y}).z()));
    for (const Occluder& o : scenario_.occluders) {
        const double middle = (o.azimuth_lo + o.azimuth_hi) / 2;
        occluders_.push_back({{std::cos(o.azimuth_lo), 0.0, -std::sin(o.azimuth_lo)},
                              {-std::cos(o.azimuth_hi), 0.0, std::sin(o.azimuth_hi)},
                              {std::sin(middle), 0.0, std::cos(middle)},
                              o.elevation_lo,
                              o.elevation_hi,
                              std::sin(o.elevation_lo),
                              std::sin(o.elevation_hi),
                              o.grey});
    }
}

// Whether the bar can show in a frame whose optical axis is `axis`: the frame lies within a cone of
// view_reach_rad_ about the axis, whose elevations span ±that angle about the axis's and whose
// azimuths span ±asin(sin reach / cos elevation) about its (all of them when it holds a pole).
bool SimCamera::occluder_in_view(const Occluder& occluder, const Eigen::Vector3d& axis) const {
    const double reach = view_reach_rad_ + pixel_reach_rad_;
    const control::WorldAngles towards = control::angles_of(axis);
    if (occluder.elevation_lo > towards.elevation + reach || occluder.elevation_hi < towards.elevation - reach)
        return false;
    if (std::abs(towards.elevation) + reach >= std::numbers::pi / 2) return true;
    const double azimuth_reach = std::asin(std::min(1.0, std::sin(reach) / std::cos(towards.elevation)));
    const double middle = (occluder.azimuth_lo + occluder.azimuth_hi) / 2;
    const double half_width = (occluder.azimuth_hi - occluder.azimuth_lo) / 2;
    return std::abs(control::angle_difference(middle, towards.azimuth)) <= azimuth_reach + half_width;
}

double SimCamera::occluder_coverage(const OccluderGeometry& bar, const Eigen::Vector3d& ray, double norm,
                                    double elevation, const Eigen::Vector3d& step_x,
                                    const Eigen::Vector3d& step_y) const {
    // At the pixel's centre: the sines of the angles to the two side planes, and the elevation.
    const double reach = pixel_reach_rad_;
    const double low = ray.dot(bar.low_side) / norm, high = ray.dot(bar.high_side) / norm;
    if (ray.dot(bar.facing) <= 0 || low < -reach || high < -reach || elevation < bar.elevation_lo - reach ||
        elevation > bar.elevation_hi + reach)
        return 0.0;
    if (low > reach && high > reach && elevation > bar.elevation_lo + reach && elevation < bar.elevation_hi - reach)
        return 1.0;
    int inside = 0;
    for (double sy : kSubOffsets)
        for (double sx : kSubOffsets) {
            const Eigen::Vector3d d = ray + sx * step_x + sy * step_y;
            const double n = d.norm(), up = -d.y();
            inside += d.dot(bar.low_side) >= 0 && d.dot(bar.high_side) >= 0 && d.dot(bar.facing) > 0 &&
                      up >= bar.sin_lo * n && up <= bar.sin_hi * n;
        }
    return inside / kSamplesPerPixel;
}

void SimCamera::render(double t_s, double pan_rad, double tilt_rad, SimView& out) const {
    const Eigen::Matrix3d to_world = control::camera_to_world(pan_rad, tilt_rad);
    const control::Intrinsics& k = camera_.intrinsics();
    const FrameGeometry frame{to_world.col(2), to_world.col(0) / k.fx, to_world.col(1) / k.fy, view_reach_rad_,
                              pixel_reach_rad_};

    std::array<PlacedTarget, kMaxTargets> placed;
    std::size_t placed_count = 0;
    for (std::size_t i = 0; i < scenario_.targets.size(); ++i) {
        const std::uint64_t texture_seed = scenario_.seed * 0x2545F4914F6CDD1Dull + i + 1;
        if (auto p = place(scenario_.targets[i], t_s, frame, texture_seed, i == scenario_.primary))
            placed[placed_count++] = *p;
    }
    std::array<const OccluderGeometry*, kMaxOccluders> bars;
    std::size_t bar_count = 0;
    for (std::size_t i = 0; i < occluders_.size(); ++i)
        if (occluder_in_view(scenario_.occluders[i], frame.axis)) bars[bar_count++] = &occluders_[i];

    const double gain = scenario_.exposure.gain(t_s), sigma = scenario_.noise_sigma;
    scenes::Random random(frame_seed(scenario_.seed, t_s));
    double own_area = 0, visible_area = 0, mask_count = 0, mask_x = 0, mask_y = 0;
    for (int y = 0; y < kFrameSize; ++y)
        for (int x = 0; x < kFrameSize; ++x) {
            const Eigen::Vector3d ray = to_world * rays_[static_cast<std::size_t>(y * kFrameSize + x)];
            const double norm = ray.norm();
            const double elevation = std::asin(std::clamp(-ray.y() / norm, -1.0, 1.0));
            double grey = panorama_.grey(std::atan2(ray.x(), ray.z()), elevation);
            double primary = 0;  // the primary target's visible coverage of this pixel
            for (std::size_t i = 0; i < placed_count; ++i) {
                const PlacedTarget& p = placed[i];
                const double depth = ray.dot(p.centre);
                if (depth < p.cos_reach * norm) continue;
                const PlaneDots at{ray.dot(p.east), ray.dot(p.down), depth};
                const double u = kWorldPxPerRad * at.east / depth, v = kWorldPxPerRad * at.down / depth;
                if (!p.bounds.inside(u, v)) continue;
                const double cover =
                    std::visit([&](const auto& shape) { return outline_coverage(shape, p, at); }, p.shape);
                if (cover == 0) continue;
                grey += cover * (target_grey(p, u, v) - grey);
                if (p.primary) {
                    primary = cover;
                    own_area += cover;
                } else {
                    primary *= 1 - cover;
                }
            }
            for (std::size_t i = 0; i < bar_count; ++i) {
                const double cover = occluder_coverage(*bars[i], ray, norm, elevation, frame.step_x, frame.step_y);
                grey += cover * (bars[i]->grey - grey);
                primary *= 1 - cover;
            }
            const double value = gain * grey + (sigma > 0 ? sigma * unit_noise(random) : 0.0);
            out.image.at(x, y) = static_cast<std::uint8_t>(std::clamp(value, 0.0, 255.0) + 0.5);
            visible_area += primary;
            const bool masked = primary >= 0.5;
            out.mask.at(x, y) = masked ? 255 : 0;
            if (masked) {
                mask_count += 1;
                mask_x += x;
                mask_y += y;
            }
        }

    SimTruth& truth = out.truth;
    describe_centre(scenario_.targets[scenario_.primary].path->at(t_s), camera_, to_world, truth);
    truth.in_view = mask_count > 0;
    truth.mask_centroid_px = truth.in_view ? Point{mask_x / mask_count, mask_y / mask_count} : Point{kNaN, kNaN};
    truth.visible_px = visible_area;
    truth.visible_fraction = own_area > 0 ? visible_area / own_area : 0.0;
}

}  // namespace rays::sim
