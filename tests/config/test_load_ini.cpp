// SPDX-License-Identifier: Apache-2.0
#include <catch2/catch.hpp>

#include "config/tracker_config_io.hpp"
#include "temp_ini_file.hpp"

using namespace rays;
using namespace rays::config;
using rays::test::TempIniFile;

namespace {

// A config that differs from the defaults in every section, to see that load_ini leaves it alone.
TrackerConfig marked_config() {
    TrackerConfig config;
    config.tunables.rays.alpha = 0.7;
    config.tunables.detect.threshold = 33.0;
    return config;
}

std::optional<ConfigError> load_text(const std::string& text, TrackerConfig& out) {
    TempIniFile file(text);
    return load_ini(file.path(), out);
}

}  // namespace

TEST_CASE("a file setting every section parses", "[config][ini]") {
    const std::string text =
        "; tracker settings\n"
        "# written for the test\n"
        "\n"
        "[rays]\n"
        "max_rays = 1024\n"
        "count = 512   ; inline comment\n"
        "hypotheses = 5\n"
        "alpha = 0.05\n"
        "lambda_max_px = 70\n"
        "\n"
        "[detect]\n"
        "threshold = 25.5\n"
        "min_area_px = 20\n"
        "\n"
        "[attention]\n"
        "lost_frames = 3\n"
        "max_jump_px: 12\n"  // libinih also takes ':' like Python's configparser
        "\n"
        "[track]\n"
        "predict = off\n";
    TrackerConfig config = marked_config();
    auto error = load_text(text, config);
    INFO((error ? error->to_string() : "no error"));
    REQUIRE_FALSE(error);
    CHECK(config.capacity.max_rays == 1024);
    CHECK(config.capacity.max_hypotheses == 6);  // absent: default
    CHECK(config.tunables.rays.count == 512);
    CHECK(config.tunables.rays.hypotheses == 5);
    CHECK(config.tunables.rays.alpha == 0.05);
    CHECK(config.tunables.rays.lambda_max_px == 70.0);
    CHECK(config.tunables.rays.beta == rays::RaysTunables{}.beta);  // absent keys keep the default
    CHECK(config.tunables.detect.threshold == 25.5);  // the marked 33 is replaced
    CHECK(config.tunables.detect.min_area_px == 20);
    CHECK(config.tunables.attention.lost_frames == 3);
    CHECK(config.tunables.attention.max_jump_px == 12.0);
    CHECK_FALSE(config.tunables.predict);
}

TEST_CASE("an empty file gives the defaults", "[config][ini]") {
    TrackerConfig config = marked_config();
    REQUIRE_FALSE(load_text("", config));
    CHECK(to_json(config) == to_json(TrackerConfig{}));
}

TEST_CASE("each kind of error names its line, counting comments and blank lines", "[config][ini]") {
    // Lines 1-3 are a ';' comment, a '#' comment and a blank line; the error is on `line`.
    const std::string preamble = "; comment\n# another comment\n\n";
    struct Case {
        const char* what;
        std::string body;
        int line;
        const char* message;
    };
    const std::vector<Case> cases = {
        {"out of range", "[rays]\nbeta = 0.1\nalpha = -1\n", 6, "rays.alpha = -1 is out of range [0, 10]"},
        {"not a number", "[rays]\n\nalpha = fast\n", 6, "rays.alpha = fast is not a number"},
        {"trailing junk", "[rays]\ncount = 36x\n", 5, "rays.count = 36x is not an integer (unexpected 'x')"},
        {"not an integer", "[rays]\ncount = 3.5\n", 5, "rays.count = 3.5 is not an integer (unexpected '.5')"},
        {"bad bool", "[track]\npredict = maybe\n", 5,
         "track.predict = maybe is not a boolean (use true/false, yes/no, on/off or 1/0)"},
        {"unknown key", "[rays]\nalpha = 0.1\n; note\nalpah = 0.2\n", 7,
         "unknown parameter rays.alpah (did you mean rays.alpha?)"},
        {"unknown key far from any", "[rays]\nzoom = 2\n", 5, "unknown parameter rays.zoom"},
        {"unknown section", "[rays]\nalpha = 0.1\n[detcet]\nthreshold = 9\n", 6,
         "unknown section [detcet] (did you mean [detect]?)"},
        {"unknown empty section", "[camera]\n", 4, "unknown section [camera]"},
        {"duplicate key", "[rays]\nalpha = 0.1\n\n[detect]\n[rays]\nalpha = 0.2\n", 9,
         "rays.alpha is set twice (first on line 5)"},
        {"key before any section", "alpha = 0.1\n", 4,
         "key alpha comes before any [section] header (rays.alpha belongs under [rays])"},
        {"syntax", "[rays]\nalpha 0.1\n", 5, "expected [section], key = value or a comment, not 'alpha 0.1'"},
        {"unclosed section", "[rays\nalpha = 0.1\n", 4, "expected [section], key = value or a comment, not '[rays'"},
        {"continued value", "[rays]\nalpha = 0.1\n  beta = 0.2\n", 6,
         "indented line would continue the value of alpha; multi-line values are not supported, remove the "
         "indentation"},
        {"no value", "[rays]\nalpha =\n", 5, "rays.alpha has no value"},
        {"overlong line", "[rays]\n;" + std::string(300, 'x') + "\n", 5, "line is longer than 198 characters"},
        {"first of two errors", "[rays]\nalpha = x\nbeta = y\n", 5, "rays.alpha = x is not a number"},
        {"syntax error before a value error", "[rays]\noops\nalpha = x\n", 5,
         "expected [section], key = value or a comment, not 'oops'"},
    };
    for (const Case& test : cases) {
        INFO(test.what);
        TrackerConfig config = marked_config();
        TempIniFile file(preamble + test.body);
        auto error = load_ini(file.path(), config);
        REQUIRE(error);
        CHECK(error->file == file.path());
        CHECK(error->line == test.line);
        CHECK(error->message == test.message);
        CHECK(error->to_string() == file.path() + ":" + std::to_string(test.line) + ": " + test.message);
        CHECK(to_json(config) == to_json(marked_config()));  // untouched on error
    }
}

TEST_CASE("windows line ends and a byte order mark are accepted", "[config][ini]") {
    TrackerConfig config;
    REQUIRE_FALSE(load_text("\xEF\xBB\xBF[rays]\r\nalpha = 0.25\r\n\r\n[track]\r\npredict = no\r\n", config));
    CHECK(config.tunables.rays.alpha == 0.25);
    CHECK_FALSE(config.tunables.predict);
}

TEST_CASE("cross-field rules blame the last key they relate that the file sets", "[config][ini]") {
    struct Case {
        const char* what;
        std::string text;
        int line;
        const char* message;
    };
    const std::vector<Case> cases = {
        {"capacity below the default count", "[rays]\n\nmax_rays = 100\n", 3,
         "rays.count = 360 must be <= rays.max_rays = 100"},
        {"count above capacity", "[rays]\nmax_rays = 400\nalpha = 0.1\ncount = 500\n", 4,
         "rays.count = 500 must be <= rays.max_rays = 400"},
        {"hypotheses above capacity", "[rays]\nhypotheses = 7\n", 2,
         "rays.hypotheses = 7 must be <= rays.max_hypotheses = 6"},
        {"lambda range empty", "[rays]\nlambda_min_px = 70\nlambda_max_px = 70\n", 3,
         "rays.lambda_min_px = 70 must be < rays.lambda_max_px = 70"},
        {"too many samples", "[rays]\nstep_px = 0.25\n", 2,
         "rays.lambda_min_px to rays.lambda_max_px in steps of rays.step_px gives 233 samples per ray, more than "
         "rays.max_samples = 160"},
        {"centroid rays above count", "[rays]\ncount = 16\nmax_rays = 16\n", 2,
         "rays.centroid_rays = 32 must be <= rays.count = 16"},
        {"threshold below its minimum", "[detect]\nthreshold = 5\n", 2,
         "detect.threshold_min = 6 must be <= detect.threshold = 5"},
        {"threshold above its maximum", "[detect]\nthreshold_max = 10\n", 2,
         "detect.threshold = 20 must be <= detect.threshold_max = 10"},
    };
    for (const Case& test : cases) {
        INFO(test.what);
        TrackerConfig config = marked_config();
        auto error = load_text(test.text, config);
        REQUIRE(error);
        CHECK(error->line == test.line);
        CHECK(error->message == test.message);
        CHECK(to_json(config) == to_json(marked_config()));
    }
    TrackerConfig config;
    CHECK_FALSE(load_text("[rays]\nmax_samples = 240\nstep_px = 0.25\n", config));  // 233 samples fit now
    CHECK(config.tunables.rays.step_px == 0.25);
}

TEST_CASE("a missing file is an error on line 0", "[config][ini]") {
    TrackerConfig config = marked_config();
    auto error = load_ini("/nonexistent/rays.ini", config);
    REQUIRE(error);
    CHECK(error->line == 0);
    CHECK(error->to_string() == "/nonexistent/rays.ini:0: cannot open: No such file or directory");
    CHECK(to_json(config) == to_json(marked_config()));
}
