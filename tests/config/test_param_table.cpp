// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include <cstddef>
#include <set>

#include "config/config_table.hpp"
#include "config/tracker_config_io.hpp"

using namespace rays;
using namespace rays::config;

namespace {

// Counts the members of an aggregate: the most initialisers T{...} accepts. Fails the coverage
// test below when a field is added to tracker_config.hpp without a table entry.
struct AnyField {
    template <class T>
    operator T() const;
};

template <class T, class... Fields>
constexpr std::size_t field_count() {
    if constexpr (requires { T{Fields{}..., AnyField{}}; })
        return field_count<T, Fields..., AnyField>();
    else
        return sizeof...(Fields);
}

// A value of the parameter's type different from `value` (for a choice: the next word).
ParamValue other_value(const ParamInfo& info, const ParamValue& value) {
    if (const int* number = std::get_if<int>(&value)) return *number + 1;
    if (const bool* flag = std::get_if<bool>(&value)) return !*flag;
    if (const std::string* word = std::get_if<std::string>(&value)) {
        const int k = choice_index(info.choices, *word);
        const std::string_view next = choice_word(info.choices, k + 1);
        return std::string(next.empty() ? choice_word(info.choices, 0) : next);
    }
    return std::get<double>(value) + 0.5;
}

}  // namespace

TEST_CASE("the table has one entry for every field of TrackerConfig", "[config][table]") {
    STATIC_REQUIRE(field_count<TrackerConfig>() == 3);    // capacity, tunables, method
    STATIC_REQUIRE(field_count<TrackerTunables>() == 5);  // rays, detect, attention, snake, predict
    constexpr std::size_t leaf_fields = field_count<TrackerCapacity>() + field_count<RaysTunables>() +
                                        field_count<DetectTunables>() + field_count<AttentionTunables>() +
                                        field_count<SnakeTunables>() + 2;
    CHECK(tracker_params().params().size() == leaf_fields);

    // ... and no two entries reach the same field, so the entries cover every field.
    const auto& params = tracker_params().params();
    for (const auto& changed : params) {
        TrackerConfig config;
        changed.write(config, other_value(changed.info, changed.read(config)));
        INFO("changed " << changed.info.name);
        for (const auto& other : params) {
            INFO("read " << other.info.name);
            CHECK((other.read(config) == other.info.default_value) == (&other != &changed));
        }
    }
}

TEST_CASE("table defaults are the struct's defaults and satisfy the table", "[config][table]") {
    const TrackerConfig defaults{};
    for (const auto& param : tracker_params().params()) {
        INFO(param.info.name);
        CHECK(param.info.default_value == param.read(defaults));
        if (param.info.type == ParamType::Choice) {
            CHECK(std::holds_alternative<std::string>(param.info.default_value));
            continue;
        }
        CHECK(param.info.default_value.index() == static_cast<std::size_t>(param.info.type));
        if (param.info.type != ParamType::Bool) {
            CHECK(value_as_number(param.info.default_value) >= param.info.min);
            CHECK(value_as_number(param.info.default_value) <= param.info.max);
        }
    }
    CHECK_FALSE(tracker_params().check_rules(defaults));
    CHECK(defaults.tunables.rays.alpha == 0.02);  // spot check against the header
    CHECK(std::get<double>(tracker_params().find("rays.alpha")->info.default_value) == 0.02);
    CHECK(std::get<int>(tracker_params().find("rays.max_rays")->info.default_value) == 720);
}

TEST_CASE("names, kinds and sections follow tracker_config.hpp", "[config][table]") {
    std::set<std::string> capacities;
    for (const ParamInfo* info : list_params())
        if (info->kind == ParamKind::Capacity) capacities.insert(info->name);
    CHECK(capacities == std::set<std::string>{"rays.max_rays", "rays.max_hypotheses", "rays.max_samples",
                                              "track.method", "snake.max_points"});
    CHECK(tracker_params().sections() ==
          std::vector<std::string_view>{"rays", "detect", "attention", "track", "snake"});
    for (const char* name : {"rays.count", "rays.centroid_tol_px", "detect.max_area_fraction", "attention.lost_frames",
                             "attention.min_area_px", "detect.min_area_px", "track.predict"})
        CHECK(tracker_params().find(name) != nullptr);
    CHECK(tracker_params().find("track.predict")->info.type == ParamType::Bool);
    CHECK(list_params().size() == tracker_params().params().size());
}

TEST_CASE("every cross-field rule names parameters of the table", "[config][table]") {
    REQUIRE(tracker_params().rules().size() == 9);
    for (const CrossRule& rule : tracker_params().rules())
        for (const std::string& key : rule.keys) {
            INFO(key);
            CHECK(tracker_params().find(key) != nullptr);
        }
}

TEST_CASE("to_json has every parameter with its value", "[config][table]") {
    TrackerConfig config;
    config.tunables.rays.alpha = 0.5;
    config.tunables.predict = false;
    nlohmann::json settings = to_json(config);
    CHECK(settings.size() == tracker_params().params().size());
    for (const ParamInfo* info : list_params()) CHECK(settings.contains(info->name));
    CHECK(settings["rays.alpha"] == 0.5);
    CHECK(settings["rays.max_rays"] == 720);
    CHECK(settings["track.predict"] == false);
    CHECK(settings["rays.count"].is_number_integer());
}

TEST_CASE("samples per ray follow floor((max - min) / step) + 1", "[config][table]") {
    CHECK(samples_per_ray(2.0, 60.0, 0.5) == 117);
    CHECK(samples_per_ray(0.0, 10.0, 3.0) == 4);
    CHECK(samples_per_ray(5.0, 5.0, 1.0) == 1);
}

TEST_CASE("track.method is a choice fixed at start, read into the TrackerMethod enum", "[config][table]") {
    const ParamInfo& info = tracker_params().find("track.method")->info;
    CHECK(info.type == ParamType::Choice);
    CHECK(info.default_value == ParamValue{std::string("rays")});
    TrackerConfig config;
    CHECK(set_param(config, "track.method", "snake", false).has_value());  // a capacity
    CHECK(config.method == TrackerMethod::Rays);
    CHECK(set_param(config, "track.method", "spline", true).has_value());
    REQUIRE_FALSE(set_param(config, "track.method", "snake", true));
    CHECK(config.method == TrackerMethod::Snake);
    std::string text;
    REQUIRE_FALSE(get_param(config, "track.method", text));
    CHECK(text == "snake");
    CHECK(to_json(config)["track.method"] == "snake");
}
