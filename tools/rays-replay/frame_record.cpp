// SPDX-License-Identifier: Apache-2.0
#include "frame_record.hpp"

#include <cmath>

#include <nlohmann/json.hpp>

#include "config/tracker_config_io.hpp"

namespace rays::replay {

void write_header(std::FILE* out, int source_w, int source_h, const io::AreaScaler& scaler,
                  const TrackerConfig& config, long budget_us) {
    nlohmann::json settings = config::to_json(config);
    settings["budget_us"] = budget_us;
    const nlohmann::json header = {
        {"source", {{"width", source_w}, {"height", source_h}}},
        {"proc", {{"width", kFrameSize}, {"height", kFrameSize}}},
        {"scale", {scaler.scale_x(), scaler.scale_y()}},
        {"offset", {scaler.offset_x(), scaler.offset_y()}},
        {"config", settings},
    };
    std::fprintf(out, "%s\n", header.dump().c_str());
}

void write_frame(std::FILE* out, const Tracker& tracker, double time_us, bool crossings) {
    const FrameResult& r = tracker.result();
    const Contour& c = tracker.contour();
    std::fprintf(out, "{\"frame\":%ld,\"state\":\"%s\",", r.frame, to_string(r.state));
    if (r.has_contour) {
        std::fprintf(out, "\"ref\":[%.2f,%.2f],\"contour\":[", c.ref.x, c.ref.y);
        for (int i = 0; i < c.size; ++i)
            std::fprintf(out, "%s[%.2f,%.2f]", i ? "," : "", c.points[i].p.x, c.points[i].p.y);
        std::fprintf(out, "],\"rays\":%d,\"levels\":%d,\"deadline_hit\":%s,\"psr\":%.1f", c.size, c.levels,
                     c.deadline_hit ? "true" : "false", r.match_psr);
        if (crossings) {
            // Further accepted crossings per ray (concave parts), as image points.
            std::fprintf(out, ",\"crossings\":[");
            bool first = true;
            for (int i = 0; i < c.size; ++i) {
                const ContourPoint& p = c.points[i];
                for (int k = 0; k < c.crossing_count[i]; ++k) {
                    const double lam = c.crossing(i, k);
                    std::fprintf(out, "%s{\"ray\":%d,\"point\":[%.2f,%.2f]}", first ? "" : ",", i,
                                 c.ref.x + lam * std::cos(p.phi), c.ref.y + lam * std::sin(p.phi));
                    first = false;
                }
            }
            std::fprintf(out, "]");
        }
    } else {
        std::fprintf(out, "\"ref\":null,\"contour\":[],\"rays\":0,\"levels\":0,\"deadline_hit\":false,\"psr\":0");
    }
    if (r.lost_reason != nullptr)
        std::fprintf(out, ",\"lost_reason\":%s", nlohmann::json(r.lost_reason).dump().c_str());
    std::fprintf(out, ",\"time_us\":%.1f}\n", time_us);
}

}  // namespace rays::replay
