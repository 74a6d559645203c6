// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "config/name_suggestion.hpp"
#include "config/param_text.hpp"

using namespace rays::config;

namespace {

ParamInfo int_param() { return {"rays.count", ParamType::Int, ParamKind::Tunable, "rays", 4, 4096, 360, "doc", {}}; }
ParamInfo real_param() { return {"rays.alpha", ParamType::Double, ParamKind::Tunable, "", 0, 10, 0.02, "doc", {}}; }
ParamInfo bool_param() { return {"track.predict", ParamType::Bool, ParamKind::Tunable, "", 0, 1, true, "doc", {}}; }

}  // namespace

TEST_CASE("parse_value reads ints, reals and the boolean words", "[config][text]") {
    ParamValue value;
    CHECK_FALSE(parse_value(int_param(), " 720 ", value));
    CHECK(value == ParamValue{720});
    CHECK_FALSE(parse_value(real_param(), "1e-3", value));
    CHECK(value == ParamValue{0.001});
    for (const char* word : {"true", "YES", "on", "1"}) {
        CHECK_FALSE(parse_value(bool_param(), word, value));
        CHECK(value == ParamValue{true});
    }
    for (const char* word : {"false", "No", "off", "0"}) {
        CHECK_FALSE(parse_value(bool_param(), word, value));
        CHECK(value == ParamValue{false});
    }
}

TEST_CASE("parse_value rejects bad text and leaves the value alone", "[config][text]") {
    ParamValue value = 7;
    CHECK(parse_value(int_param(), "abc", value) == "rays.count = abc is not an integer");
    CHECK(parse_value(int_param(), "36.5", value) == "rays.count = 36.5 is not an integer (unexpected '.5')");
    CHECK(parse_value(int_param(), "99999999999999999999", value)->find("out of range [4, 4096] rays") !=
          std::string::npos);
    CHECK(parse_value(real_param(), "-1", value) == "rays.alpha = -1 is out of range [0, 10]");
    CHECK(parse_value(real_param(), "nan", value) == "rays.alpha = nan is not a finite number");
    CHECK(parse_value(real_param(), "", value) == "rays.alpha has no value");
    CHECK(parse_value(real_param(), "0.5 # half", value)->find("inline comment") != std::string::npos);
    CHECK(parse_value(bool_param(), "maybe", value)->find("not a boolean") != std::string::npos);
    CHECK(value == ParamValue{7});
}

TEST_CASE("format_value gives text that parses back to the same value", "[config][text]") {
    CHECK(format_value(ParamValue{360}) == "360");
    CHECK(format_value(ParamValue{false}) == "false");
    CHECK(format_value(ParamValue{720.0}) == "720");
    for (double number : {0.02, 0.002, 1.0 / 3.0, 123456.789, 1e-9}) {
        ParamValue parsed;
        REQUIRE_FALSE(parse_value(ParamInfo{"x.y", ParamType::Double, ParamKind::Tunable, "", -1e9, 1e9, 0.0, "", {}},
                                  format_value(ParamValue{number}), parsed));
        CHECK(std::get<double>(parsed) == number);
    }
}

TEST_CASE("edit distance counts swaps of neighbours as one edit", "[config][text]") {
    CHECK(edit_distance("alpha", "alpha") == 0);
    CHECK(edit_distance("alpah", "alpha") == 1);
    CHECK(edit_distance("alph", "alpha") == 1);
    CHECK(edit_distance("", "abc") == 3);
    CHECK(edit_distance("kitten", "sitting") == 3);
    CHECK(closest_name("rays.alpah", {"rays.beta", "rays.alpha"}) == std::optional<std::string_view>("rays.alpha"));
    CHECK_FALSE(closest_name("rays.gamma", {"rays.beta", "rays.alpha"}));
}

TEST_CASE("text and choice parameters parse, check and print back") {
    ParamInfo path{"socket.path", ParamType::Text, ParamKind::Capacity, "", 0, 0, std::string{}, "doc", {}};
    ParamInfo source{"camera.source", ParamType::Choice, ParamKind::Capacity, "", 0, 0, std::string{}, "doc",
                     "v4l2|replay"};
    ParamValue value;
    REQUIRE_FALSE(parse_value(path, "  /run/raysd/raysd.sock ", value));
    CHECK(std::get<std::string>(value) == "/run/raysd/raysd.sock");
    REQUIRE_FALSE(parse_value(path, "", value));
    CHECK(std::get<std::string>(value).empty());
    CHECK(parse_value(path, std::string("a\x01") + "b", value).value() == "socket.path contains a control character");
    REQUIRE_FALSE(parse_value(source, "replay", value));
    CHECK(format_value(value) == "replay");
    CHECK(parse_value(source, "v4l", value).value() == "camera.source = v4l is not one of v4l2|replay");
    CHECK(parse_value(source, "", value).value() == "camera.source has no value");
    CHECK(describe_type_and_range(source) == "one of v4l2|replay");
}

TEST_CASE("text values that an INI file would cut at a comment are refused") {
    ParamInfo path{"socket.path", ParamType::Text, ParamKind::Capacity, "", 0, 0, std::string{}, "doc", {}};
    ParamValue value = std::string("kept");
    CHECK(parse_value(path, ";y", value).value() ==
          "socket.path = ;y has a ';' at its start or after a blank, where an INI file starts a comment");
    CHECK(parse_value(path, "a ;b", value));
    CHECK(std::get<std::string>(value) == "kept");
    REQUIRE_FALSE(parse_value(path, "a;b", value));
    CHECK(std::get<std::string>(value) == "a;b");
}

