// SPDX-License-Identifier: Apache-2.0
#include "replay_options.hpp"

#include <charconv>
#include <cstring>
#include <vector>

namespace rays::replay {
namespace {

// Splits "a,b,c" into numbers; false unless exactly `count` numbers and nothing else.
template <class T>
bool parse_list(const std::string& text, int count, std::vector<T>& out) {
    out.clear();
    const char* p = text.data();
    const char* end = p + text.size();
    while (p <= end) {
        T v{};
        auto [next, ec] = std::from_chars(p, end, v);
        if (ec != std::errc()) return false;
        out.push_back(v);
        if (next == end) break;
        if (*next != ',') return false;
        p = next + 1;
    }
    return static_cast<int>(out.size()) == count;
}

}  // namespace

const char* usage() {
    return "usage: rays-replay --input PATH [--out FILE] [--config FILE.ini] [--init auto|X,Y|X,Y,W,H]\n"
           "                   [--crop X,Y,W,H] [--budget-us N] [--overlay DIR] [--crossings]\n"
           "  PATH: a YUV4MPEG2 file (or - for standard input) or a folder of PGM/PNG frames.\n"
           "  --init: where the target is in the first frame, in processing pixels: a point X,Y, or a\n"
           "  box X,Y,W,H (left, top, width, height, as cv::Rect); auto (the default) detects it.\n"
           "  Writes JSON Lines: a header, then one object per frame (stdout without --out).\n";
}

std::optional<Options> parse_options(int argc, char** argv, std::string& error) {
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            error.clear();
            return std::nullopt;
        }
        if (arg == "--crossings") {
            o.crossings = true;
            continue;
        }
        if (i + 1 >= argc) {
            error = "option " + arg + " needs a value";
            return std::nullopt;
        }
        const std::string value = argv[++i];
        if (arg == "--input") {
            o.input = value;
        } else if (arg == "--out") {
            o.out = value;
        } else if (arg == "--config") {
            o.config = value;
        } else if (arg == "--overlay") {
            o.overlay_dir = value;
        } else if (arg == "--budget-us") {
            std::vector<long> v;
            if (!parse_list(value, 1, v) || v[0] < 0) {
                error = "--budget-us wants a whole number of microseconds, not '" + value + "'";
                return std::nullopt;
            }
            o.budget_us = v[0];
        } else if (arg == "--crop") {
            std::vector<int> v;
            if (!parse_list(value, 4, v) || v[2] <= 0 || v[3] <= 0 || v[0] < 0 || v[1] < 0) {
                error = "--crop wants X,Y,W,H with W and H above 0, not '" + value + "'";
                return std::nullopt;
            }
            o.crop = {v[0], v[1], v[2], v[3]};
        } else if (arg == "--init") {
            o.init.reset();
            o.box.reset();
            if (value == "auto") continue;
            std::vector<double> v;
            if (parse_list(value, 4, v)) {
                const Box box{v[0], v[1], v[2], v[3]};
                if (const char* problem = box_problem(box)) {
                    error = std::string("--init X,Y,W,H: ") + problem + ", not '" + value + "'";
                    return std::nullopt;
                }
                o.box = box;
                continue;
            }
            if (!parse_list(value, 2, v)) {
                error = "--init wants auto, a point X,Y or a box X,Y,W,H in processing pixels, not '" + value + "'";
                return std::nullopt;
            }
            if (!(v[0] >= 0 && v[1] >= 0 && v[0] <= kFrameSize - 1 && v[1] <= kFrameSize - 1)) {
                error = "--init X,Y: the point must lie in the processing frame (0 to 127), not '" + value + "'";
                return std::nullopt;
            }
            o.init = Point{v[0], v[1]};
        } else {
            error = "unknown option " + arg;
            return std::nullopt;
        }
    }
    if (o.input.empty()) {
        error = "--input PATH is required";
        return std::nullopt;
    }
    return o;
}

}  // namespace rays::replay
