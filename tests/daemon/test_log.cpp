// SPDX-License-Identifier: Apache-2.0
// Logging: sd-daemon priority prefixes for journald, the level filter, rate-limited repeats, and the
// frame loop's non-blocking queue.
#include <catch2/catch.hpp>

#include <algorithm>
#include <chrono>

#include "captured_log.hpp"
#include "daemon/log.hpp"
#include "daemon/loop_log.hpp"

using namespace rays::daemon;
using rays::test::CapturedLog;

TEST_CASE("log lines carry the sd-daemon priority prefix and respect the level") {
    CapturedLog captured;
    set_log_level(Priority::Info);
    set_log_repeat_interval(std::chrono::seconds(0));
    log(Priority::Err, "disk %s", "gone");
    log(Priority::Info, "frame %d", 7);
    log(Priority::Debug, "not shown");
    CHECK(captured.text() == "<3>disk gone\n<6>frame 7\n");
    Priority parsed = Priority::Info;
    CHECK(parse_priority("warning", parsed));
    CHECK(parsed == Priority::Warning);
    CHECK_FALSE(parse_priority("loud", parsed));
}

TEST_CASE("a repeated message is written once per interval, then with the count held back") {
    CapturedLog captured;
    set_log_level(Priority::Info);
    set_log_repeat_interval(std::chrono::hours(1));  // however slow the machine, the repeats fall within it
    for (int i = 0; i < 5; ++i) log(Priority::Warning, "camera away (%d)", i);
    log(Priority::Warning, "another message");
    CHECK(captured.text() == "<4>camera away (0)\n<4>another message\n");
    set_log_repeat_interval(std::chrono::seconds(0));  // the interval has passed
    log(Priority::Warning, "camera away (%d)", 5);
    CHECK(captured.text() == "<4>camera away (0)\n<4>another message\n<4>camera away (5) (repeated 4 more times)\n");
}

TEST_CASE("the frame loop's log lines wait in a bounded queue until drained, overflow is counted") {
    CapturedLog captured;
    set_log_level(Priority::Info);
    set_log_repeat_interval(std::chrono::seconds(0));
    LoopLog loop_log;
    for (int i = 0; i < 70; ++i) loop_log.log(Priority::Notice, "frame %d late", i);
    CHECK(captured.text().empty());  // nothing written by the loop itself
    CHECK(loop_log.dropped() == 6);
    loop_log.drain();
    std::string text = captured.text();
    CHECK(std::count(text.begin(), text.end(), '\n') == 64);
    CHECK(text.rfind("<5>frame 0 late\n", 0) == 0);
}
