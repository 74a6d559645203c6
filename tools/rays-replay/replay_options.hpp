// SPDX-License-Identifier: Apache-2.0
// Command line of rays-replay.
#pragma once
#include <optional>
#include <string>

#include "core/box.hpp"
#include "core/image.hpp"
#include "io/area_scaler.hpp"

namespace rays::replay {

struct Options {
    std::string input;
    std::string out;          // empty: standard output
    std::string config;       // INI file with [rays], [detect], [attention], [track]
    std::string overlay_dir;  // empty: no overlays
    io::Crop crop;
    std::optional<Point> init;  // a point start, processing pixels; with neither, detect automatically
    std::optional<Box> box;     // a box start (core/box.hpp), processing pixels
    long budget_us = 0;         // 0: no deadline
    bool crossings = false;
};

// Parses argv; on failure returns nothing and sets `error` (empty error with no options = --help).
std::optional<Options> parse_options(int argc, char** argv, std::string& error);
const char* usage();

}  // namespace rays::replay
