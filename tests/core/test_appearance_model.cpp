// SPDX-License-Identifier: Apache-2.0
// The target's colours against its surroundings (core/appearance_model.hpp) on scenes drawn here: a
// disc whose grey is the same blocky texture as its background's and whose only difference is its
// colour, on a background that pans the other way.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <vector>

#include "core/appearance_model.hpp"
#include "core/tracker.hpp"
#include "scenes/scene.hpp"
#include "support/block_texture.hpp"

namespace {

using rays::AppearanceModel;
using rays::Chroma;
using rays::Contour;
using rays::GreyImage;
using rays::LikelihoodMap;
using rays::Point;

using rays::test::block_hash;
using rays::test::floor_div;

// Grey in 3-px blocks from 60 to 180 everywhere, target and background alike; the background's
// colours are greens and blues in 6-px blocks, the target's reds.
struct ColourScene {
    static constexpr double kRadius = 14.0;
    double pan_px_per_frame = -1.0;      // the background's motion (a turning camera)
    double target_px_per_frame = 1.5;    // the target's, to the right
    Point start{40.0, 64.0};

    Point centre(int frame) const { return {start.x + target_px_per_frame * frame, start.y}; }

    void render(int frame, GreyImage& luma, Chroma& chroma, GreyImage& mask) const {
        const Point c = centre(frame);
        const int shift = static_cast<int>(std::lround(pan_px_per_frame * frame));
        const int target_shift = static_cast<int>(std::lround(target_px_per_frame * frame));
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x) {
                const bool on = std::hypot(x - c.x, y - c.y) <= kRadius;
                const int u = on ? x - target_shift : x - shift;
                luma.at(x, y) = static_cast<std::uint8_t>(60 + block_hash(floor_div(u, 3), y / 3, on ? 2u : 1u) % 121);
                mask.at(x, y) = on ? 255 : 0;
            }
        chroma.present = true;
        for (int j = 0; j < rays::kChromaSize; ++j)
            for (int i = 0; i < rays::kChromaSize; ++i) {
                const int x = 2 * i, y = 2 * j;
                const bool on = std::hypot(x + 0.5 - c.x, y + 0.5 - c.y) <= kRadius;
                const std::uint32_t h = block_hash(floor_div(x - shift, 6), y / 6, 3u);
                const auto k = static_cast<std::size_t>(j * rays::kChromaSize + i);
                chroma.u[k] = static_cast<std::uint8_t>(on ? 96 + h % 8 : 136 + h % 40);   // Cb: reds low, greens/blues high
                chroma.v[k] = static_cast<std::uint8_t>(on ? 184 + h % 8 : 80 + h % 48);   // Cr: reds high
            }
    }
};

struct Frame {
    GreyImage luma, mask;
    Chroma chroma;
};

// A circle of `n` points round `c`, as a contour (ordered by angle).
void circle(Contour& contour, Point c, double r, int n) {
    contour.size = n;
    for (int k = 0; k < n; ++k) {
        const double a = 2.0 * std::numbers::pi * k / n;
        contour.points[static_cast<std::size_t>(k)].p = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
    }
    rays::polygon_area_centroid(contour.points.data(), n, contour.area, contour.centroid);
}

// The mean log-odds of the cells whose centres lie between `from` and `to` px from `c`.
double mean_log_odds(const LikelihoodMap& map, Point c, double from, double to) {
    double sum = 0.0;
    int n = 0;
    for (int j = 0; j < LikelihoodMap::kSize; ++j)
        for (int i = 0; i < LikelihoodMap::kSize; ++i) {
            const double d = std::hypot(2.0 * i + 0.5 - c.x, 2.0 * j + 0.5 - c.y);
            if (d < from || d > to) continue;
            sum += map.cell(i, j);
            ++n;
        }
    REQUIRE(n > 0);
    return sum / n;
}

}  // namespace

TEST_CASE("Colours learned from a contour round the target tell its inside from the background", "[appearance]") {
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    scene.render(0, f->luma, f->chroma, f->mask);
    Contour contour(rays::TrackerCapacity{});
    circle(contour, scene.centre(0), ColourScene::kRadius, 90);
    AppearanceModel model;
    REQUIRE(model.learn(f->luma, f->chroma, contour, 1.0f));
    REQUIRE(model.valid());

    // Another frame: the target and the background have both moved, their textures with them.
    scene.render(10, f->luma, f->chroma, f->mask);
    auto map = std::make_unique<LikelihoodMap>();
    model.likelihood(f->luma, f->chroma, *map);
    const Point c = scene.centre(10);
    CHECK(mean_log_odds(*map, c, 0.0, ColourScene::kRadius - 2.0) > 2.0);
    CHECK(mean_log_odds(*map, c, ColourScene::kRadius + 2.0, 40.0) < -2.0);
    // Between cell centres the map interpolates: from clearly target to clearly not across the rim.
    CHECK(map->at(static_cast<float>(c.x), static_cast<float>(c.y)) > 2.0f);
    CHECK(map->at(static_cast<float>(c.x + 30.0), static_cast<float>(c.y)) < -2.0f);
}

TEST_CASE("A point's seed tells the target's colours from those of a ring round it", "[appearance]") {
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    scene.render(0, f->luma, f->chroma, f->mask);
    AppearanceModel model;
    REQUIRE(model.seed(f->luma, f->chroma, scene.centre(0), 3.0, 20.0, 30.0));
    auto map = std::make_unique<LikelihoodMap>();
    model.likelihood(f->luma, f->chroma, *map);
    CHECK(mean_log_odds(*map, scene.centre(0), 0.0, ColourScene::kRadius - 2.0) > 1.0);
    CHECK(mean_log_odds(*map, scene.centre(0), ColourScene::kRadius + 2.0, 40.0) < -1.0);
}

TEST_CASE("A box's seed learns the box as the target and a band round it as the background", "[appearance]") {
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    scene.render(0, f->luma, f->chroma, f->mask);
    const Point c = scene.centre(0);
    const double r = ColourScene::kRadius;
    const rays::Box box{c.x - r, c.y - r, 2.0 * r + 1.0, 2.0 * r + 1.0};  // the disc's bounding box
    AppearanceModel model;
    REQUIRE(model.seed_box(f->luma, f->chroma, box, 6.0));
    auto map = std::make_unique<LikelihoodMap>();
    model.likelihood(f->luma, f->chroma, *map);
    CHECK(mean_log_odds(*map, c, 0.0, r - 2.0) > 2.0);
    CHECK(mean_log_odds(*map, c, r * std::numbers::sqrt2 + 2.0, 40.0) < -1.0);  // beyond the box's corners
    // The box's corners hold background, and so does the band: not the target, though inside the box.
    double corners = 0.0;
    int n = 0;
    for (int j = 0; j < LikelihoodMap::kSize; ++j)
        for (int i = 0; i < LikelihoodMap::kSize; ++i) {
            const double x = 2.0 * i + 0.5, y = 2.0 * j + 0.5;
            const bool in_box = x >= box.x + 1.0 && x <= box.x + box.w - 2.0 && y >= box.y + 1.0 && y <= box.y + box.h - 2.0;
            if (!in_box || std::hypot(x - c.x, y - c.y) < r + 2.0) continue;
            corners += map->cell(i, j);
            ++n;
        }
    REQUIRE(n > 0);
    CHECK(corners / n < 0.0);
    f->chroma.present = false;  // a mono source
    CHECK_FALSE(model.seed_box(f->luma, f->chroma, box, 6.0));
}

TEST_CASE("Without colour, or from too little, the model learns nothing", "[appearance]") {
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    scene.render(0, f->luma, f->chroma, f->mask);
    Contour contour(rays::TrackerCapacity{});
    AppearanceModel model;

    f->chroma.present = false;  // a mono source
    circle(contour, scene.centre(0), ColourScene::kRadius, 90);
    CHECK_FALSE(model.learn(f->luma, f->chroma, contour, 1.0f));
    CHECK_FALSE(model.seed(f->luma, f->chroma, scene.centre(0), 3.0, 20.0, 30.0));
    CHECK_FALSE(model.valid());

    f->chroma.present = true;
    circle(contour, scene.centre(0), 2.0, 12);  // no cell lies wholly inside it
    CHECK_FALSE(model.learn(f->luma, f->chroma, contour, 1.0f));
    CHECK_FALSE(model.valid());
    circle(contour, scene.centre(0), ColourScene::kRadius, 90);
    CHECK(model.learn(f->luma, f->chroma, contour, 1.0f));
    model.reset();
    CHECK_FALSE(model.valid());
}

TEST_CASE("Learning at a rate blends the new colours into the old", "[appearance]") {
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    scene.render(0, f->luma, f->chroma, f->mask);
    Contour around(rays::TrackerCapacity{}), beside(rays::TrackerCapacity{});
    circle(around, scene.centre(0), ColourScene::kRadius, 90);
    circle(beside, {100.0, 64.0}, ColourScene::kRadius, 90);  // a patch of background taken for the target
    auto map = std::make_unique<LikelihoodMap>();
    const Point target = scene.centre(0);

    AppearanceModel model;
    REQUIRE(model.learn(f->luma, f->chroma, around, 1.0f));
    REQUIRE(model.learn(f->luma, f->chroma, beside, 0.1f));  // one mistaken frame
    model.likelihood(f->luma, f->chroma, *map);
    CHECK(mean_log_odds(*map, target, 0.0, ColourScene::kRadius - 2.0) > 1.0);  // still the target

    REQUIRE(model.learn(f->luma, f->chroma, beside, 1.0f));  // replaced: the target's reds now seen by
    model.likelihood(f->luma, f->chroma, *map);              // neither histogram, so even at best
    CHECK(mean_log_odds(*map, target, 0.0, ColourScene::kRadius - 2.0) <= 0.0);
}

TEST_CASE("With colour, the tracker holds a target whose grey is its panning background's texture", "[appearance][tracker]") {
    // Grey alone sees only the texture's block edges, inside and outside the target alike.
    const ColourScene scene;
    auto f = std::make_unique<Frame>();
    auto run = [&](double appearance_weight, double& worst_iou, int& tracked) {
        rays::SteadyClock clock;
        rays::TrackerConfig config;
        config.tunables.rays.appearance_weight = appearance_weight;
        auto tracker = std::make_unique<rays::Tracker>(config, clock);
        tracker->start_at(scene.centre(0));
        worst_iou = 1.0;
        tracked = 0;
        for (int i = 0; i < 40; ++i) {
            scene.render(i, f->luma, f->chroma, f->mask);
            if (tracker->process(f->luma, f->chroma, rays::TimePoint::max()).state != rays::TrackState::Tracking) {
                worst_iou = 0.0;
                continue;
            }
            ++tracked;
            const Contour& c = tracker->contour();
            std::vector<Point> p(static_cast<std::size_t>(c.size));
            for (int k = 0; k < c.size; ++k) p[static_cast<std::size_t>(k)] = c.points[static_cast<std::size_t>(k)].p;
            worst_iou = std::min(worst_iou, rays::scenes::polygon_mask_iou(p, f->mask));
        }
    };
    double colour_iou = 0.0, grey_iou = 0.0;
    int colour_tracked = 0, grey_tracked = 0;
    run(1.0, colour_iou, colour_tracked);
    run(0.0, grey_iou, grey_tracked);
    INFO("colour: worst IoU " << colour_iou << ", " << colour_tracked << " of 40 tracked; grey alone: worst IoU "
                              << grey_iou << ", " << grey_tracked << " tracked");
    CHECK(colour_tracked == 40);
    CHECK(colour_iou >= 0.75);
    CHECK(grey_iou < 0.5);  // the scene needs the colours: grey alone does not hold it
}
