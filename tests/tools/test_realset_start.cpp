// SPDX-License-Identifier: Apache-2.0
// A person's point start on real footage (../shared/realset; skipped where that folder is absent):
// the first contour is of what the person pointed at.
#include <catch2/catch.hpp>

#include <string>

#include "core/tracker.hpp"
#include "io/frame_reader.hpp"
#include "io/frame_scaler.hpp"
#include "support/skip.hpp"

TEST_CASE("A point near a pedestrian's rim starts a contour round that point, on the pedestrian", "[realset]") {
    // otb-crossing, frame 0: the pedestrian is 6 px wide (init_box 72.4–78.4 × 80.0–106.7); the
    // point is 2.4 px inside the right rim, on the legs. The first contour from there takes in the
    // road under the feet, eq. 11 moves m onto the road, and the contour ends 14 px below the point,
    // round the road (that start's track stays there: centre in box 0.0 over the sequence, 0.85
    // from the contour seen from the point); the contour seen from the point is the pedestrian's.
    const auto dir = rays::test::shared_dir_or_skip("the real-footage start test") / "realset" / "otb-crossing";
    auto opened = rays::io::open_frames((dir / "seq.y4m").string());
    REQUIRE(opened.reader);
    rays::io::FrameReader& reader = *opened.reader;
    std::string error;
    const auto scaler = rays::io::FrameScaler::make(reader.width(), reader.height(), reader.chroma_width(),
                                                    reader.chroma_height(), {}, error);
    REQUIRE(scaler);
    rays::io::SourceImage source;
    rays::GreyImage frame;
    rays::Chroma chroma;
    REQUIRE(reader.next(source) == rays::io::FrameReader::Status::Frame);
    scaler->scale(source, frame, chroma);

    rays::SteadyClock clock;
    rays::Tracker tracker(rays::TrackerConfig{}, clock);
    const rays::Point at{76.0, 98.0};
    tracker.start_at(at);
    REQUIRE(tracker.process(frame, chroma, rays::TimePoint::max()).state == rays::TrackState::Tracking);
    const rays::Contour& c = tracker.contour();
    INFO("centroid (" << c.centroid.x << ", " << c.centroid.y << "), area " << c.area);
    CHECK(rays::contour_contains(c, at));
    CHECK(c.centroid.x >= 72.4);  // the centroid on the pedestrian: inside the ground truth's box
    CHECK(c.centroid.x <= 78.4);
    CHECK(c.centroid.y >= 80.0);
    CHECK(c.centroid.y <= 106.7);
}
