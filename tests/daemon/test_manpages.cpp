// SPDX-License-Identifier: Apache-2.0
// The manual pages in docs/man: raysd.ini(5) is the parameter table's own text (kept in step by this
// test, like config/raysd.ini) and names every key `raysd --sample-config` prints, in its section.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "config/config_engine.hpp"
#include "config/ini_manpage.hpp"
#include "daemon/daemon_params.hpp"

namespace {

using namespace rays::daemon;

const std::string kManDir = std::string(RAYS_SOURCE_DIR) + "/docs/man/";

std::string read(const std::string& path) {
    std::ifstream file(path);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

}  // namespace

TEST_CASE("docs/man/raysd.ini.5 is the page the parameter table writes") {
    std::string page = read(kManDir + "raysd.ini.5");
    std::string generated = rays::config::ini_manpage(daemon_params(), rig_template(), RAYS_VERSION);
    if (page != generated) {
        std::string fresh = std::string(RAYS_BINARY_DIR) + "/raysd.ini.5";
        std::ofstream(fresh) << generated;
        FAIL_CHECK("docs/man/raysd.ini.5 is out of date: copy " << fresh << " over it");
    }
}

TEST_CASE("raysd.ini(5) documents every key of raysd --sample-config under its own section") {
    // Section and key as the sample file has them ("[camera]" then "source = v4l2")...
    std::vector<std::string> sample_keys;
    std::string section;
    for (const std::string& line : lines_of(rays::config::sample_ini(daemon_params(), rig_template()))) {
        if (line.starts_with("[")) section = line;
        else if (!line.empty() && line.front() != ';' && line.find(" = ") != std::string::npos)
            sample_keys.push_back(section + " " + line.substr(0, line.find(" = ")));
    }
    // ...and as the page has them (".SH [camera]" then ".TP" / ".B source").
    std::vector<std::string> page_keys;
    section.clear();
    std::vector<std::string> page = lines_of(read(kManDir + "raysd.ini.5"));
    for (std::size_t i = 0; i < page.size(); ++i) {
        if (page[i].starts_with(".SH ")) section = page[i].starts_with(".SH [") ? page[i].substr(4) : "";
        else if (page[i] == ".TP" && i + 1 < page.size() && page[i + 1].starts_with(".B ") && section.starts_with("["))
            page_keys.push_back(section + " " + page[i + 1].substr(3));
    }
    for (std::string& key : page_keys) {  // roff's "\-" is the file's "-"
        for (std::size_t at; (at = key.find("\\-")) != std::string::npos;) key.erase(at, 1);
    }
    REQUIRE(sample_keys.size() == daemon_params().params().size());
    CHECK(page_keys == sample_keys);
}
