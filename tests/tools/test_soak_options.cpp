// SPDX-License-Identifier: Apache-2.0
// rays-soak's command line: the run modes and what they refuse.
#include <catch2/catch.hpp>

#include <vector>

#include "soak_options.hpp"

using rays::soak::parse_options;
using rays::soak::SoakOptions;

namespace {

std::optional<std::string> parse(std::vector<const char*> args, SoakOptions& out) {
    args.insert(args.begin(), "rays-soak");
    return parse_options(static_cast<int>(args.size()), args.data(), out);
}

}  // namespace

TEST_CASE("rays-soak --compare takes the proportional gains to sweep") {
    SoakOptions o;
    REQUIRE_FALSE(parse({"--compare", "2,4.5,10", "--config", "rig.ini"}, o));
    CHECK(o.compare_gains == std::vector<double>{2, 4.5, 10});
    CHECK(o.sweep_gains.empty());
    CHECK(o.config_path == "rig.ini");
    CHECK_FALSE(o.scenario);  // the config's sim.scenario holds
}

TEST_CASE("rays-soak refuses mixed run modes, and --law or --method with --compare") {
    SoakOptions a, b, c, d, e;
    CHECK(parse({"--compare", "2", "--sweep-gain", "4"}, a));
    CHECK(parse({"--gain", "2", "--compare", "4"}, b));
    CHECK(parse({"--compare", "2", "--law", "predictive"}, c));
    CHECK(parse({"--compare", "2", "--method", "snake"}, d));
    CHECK(parse({"--compare", "2,-1"}, e));
}

TEST_CASE("rays-soak --scenario overrides the config's scenario only when given") {
    SoakOptions o;
    REQUIRE_FALSE(parse({"--scenario", "ramp", "--frames", "100"}, o));
    REQUIRE(o.scenario);
    CHECK(*o.scenario == "ramp");
    CHECK(o.frames == 100);
}

TEST_CASE("rays-soak --lockstep is a run without a budget") {
    SoakOptions o, p;
    REQUIRE_FALSE(parse({"--lockstep", "--scenario", "patrol"}, o));
    CHECK(o.lockstep);
    CHECK_FALSE(o.budget_ms);
    CHECK(parse({"--lockstep", "--budget-ms", "5"}, p));  // a budget needs real time within the frame
}

TEST_CASE("rays-soak --seeds takes a range of seeds, for one run each, and nothing that is for one run") {
    SoakOptions o;
    REQUIRE_FALSE(parse({"--seeds", "1-6", "--scenario", "patrol", "--lockstep"}, o));
    REQUIRE(o.seeds);
    CHECK(o.seeds->first == 1);
    CHECK(o.seeds->second == 6);
    CHECK_FALSE(o.seed);
    SoakOptions bad[8];
    CHECK(parse({"--seeds", "6-1"}, bad[0]));
    CHECK(parse({"--seeds", "3"}, bad[1]));
    CHECK(parse({"--seeds", "1-x"}, bad[2]));
    CHECK(parse({"--seeds", "1-2", "--seed", "4"}, bad[3]));
    CHECK(parse({"--seeds", "1-2", "--sweep-gain", "2,4"}, bad[4]));
    CHECK(parse({"--seeds", "1-2", "--trace", "t.csv"}, bad[5]));
    CHECK(parse({"--seeds", "1-2", "--plot", "p.png"}, bad[6]));
    CHECK(parse({"--seeds", "1-2", "--overlay", "ov"}, bad[7]));
}

TEST_CASE("rays-soak --overlay-window takes FROM_S,TO_S in order") {
    SoakOptions o, bad[3];
    REQUIRE_FALSE(parse({"--overlay", "ov", "--overlay-window", "1.5,4"}, o));
    CHECK(o.overlay_from_s == 1.5);
    CHECK(o.overlay_to_s == 4.0);
    CHECK(parse({"--overlay-window", "4,1.5"}, bad[0]));
    CHECK(parse({"--overlay-window", "1.5"}, bad[1]));
    CHECK(parse({"--overlay-window", "-1,2"}, bad[2]));
}
