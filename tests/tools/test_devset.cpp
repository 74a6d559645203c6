// SPDX-License-Identifier: Apache-2.0
// The tracker on the development scenes of ../shared/devset, scored like score-contours.py: mean IoU
// of the contour polygon against the ground-truth masks, 0 for frames not tracking. Guards the
// figures reached so far against regressions; skipped where ../shared is absent.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "core/tracker.hpp"
#include "io/frame_reader.hpp"
#include "scenes/scene.hpp"
#include "support/skip.hpp"

namespace {

double devset_iou(const std::string& scene) {
    const auto dir = rays::test::shared_dir_or_skip("the development-scene test") / "devset" / scene;
    auto frames = rays::io::open_frames((dir / "seq.y4m").string());
    auto masks = rays::io::open_frames((dir / "masks.y4m").string());
    REQUIRE(frames.reader);
    REQUIRE(masks.reader);
    REQUIRE(frames.reader->width() == rays::kFrameSize);
    rays::SteadyClock clock;
    rays::Tracker tracker(rays::TrackerConfig{}, clock);
    rays::io::SourceImage image, mask_image;
    rays::GreyImage frame, mask;
    double sum = 0;
    int count = 0;
    while (frames.reader->next(image) == rays::io::FrameReader::Status::Frame) {
        REQUIRE(masks.reader->next(mask_image) == rays::io::FrameReader::Status::Frame);
        std::copy(image.grey.begin(), image.grey.end(), frame.px.begin());
        std::copy(mask_image.grey.begin(), mask_image.grey.end(), mask.px.begin());
        ++count;
        if (!tracker.process(frame, rays::TimePoint::max()).has_contour) continue;
        std::vector<rays::Point> polygon(tracker.contour().size);
        for (int k = 0; k < tracker.contour().size; ++k) polygon[k] = tracker.contour().points[k].p;
        sum += rays::scenes::polygon_mask_iou(polygon, mask);
    }
    const double iou = count > 0 ? sum / count : 0.0;
    std::printf("devset %-16s mean IoU %.3f over %d frames\n", scene.c_str(), iou, count);
    return iou;
}

}  // namespace

TEST_CASE("Development scenes keep their contour quality", "[devset]") {
    CHECK(devset_iou("ellipse-clutter") >= 0.85);
    CHECK(devset_iou("star-concave") >= 0.85);
    CHECK(devset_iou("occlusion") >= 0.6);
    CHECK(devset_iou("speed-ladder") >= 0.6);
    CHECK(devset_iou("shadow-edge") >= 0.6);
    CHECK(devset_iou("walker-pole") >= 0.6);
}
