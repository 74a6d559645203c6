// SPDX-License-Identifier: Apache-2.0
// The frame path's hottest functions are built for AVX2 and for any x86-64 (RAYS_FRAME_KERNEL,
// src/common/frame_kernel.hpp), and the loader picks one. Both must give the same numbers: the same
// rays-replay run here, where the AVX2 build is picked, and under qemu-user emulating a CPU without
// AVX2 (Nehalem), where the other is, writes the same records to the last digit.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "support/block_texture.hpp"
#include "support/skip.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

// A colour stream (4:2:0) drawn here: a blocky world panning right and down, and a disc of other
// colours and its own texture crossing it, so that the colour models and the motion maps run too.
[[maybe_unused]] void write_colour_scene(const fs::path& path, int frames) {
    constexpr int n = 128, c = 64;
    std::ofstream out(path, std::ios::binary);
    out << "YUV4MPEG2 W128 H128 F25:1 Ip A1:1 C420jpeg\n";
    std::string y(n * n, '\0'), u(c * c, '\0'), v(c * c, '\0');
    for (int f = 0; f < frames; ++f) {
        const double pan_x = 0.8 * f, pan_y = 0.3 * f;               // the view moves
        const double cx = 40.0 + 1.2 * f, cy = 64.0 + 8.0 * std::sin(0.1 * f);  // the target moves on it
        auto inside = [&](double x, double yy) { return std::hypot(x - cx, yy - cy) < 14.0; };
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                y[j * n + i] = static_cast<char>(inside(i, j) ? rays::test::smooth_blocks(i - cx, j - cy, 7, 4.0, 90, 80)
                                                              : rays::test::smooth_blocks(i + pan_x, j + pan_y, 3));
        for (int j = 0; j < c; ++j)
            for (int i = 0; i < c; ++i) {
                const double x = 2 * i + 0.5, yy = 2 * j + 0.5;
                const bool in = inside(x, yy);
                u[j * c + i] = static_cast<char>(in ? 170 : rays::test::smooth_blocks(x + pan_x, yy + pan_y, 5, 8.0, 100, 50));
                v[j * c + i] = static_cast<char>(in ? 80 : rays::test::smooth_blocks(x + pan_x, yy + pan_y, 9, 8.0, 100, 50));
            }
        out << "FRAME\n" << y << u << v;
    }
}

// rays-replay's records with the time each frame took left out (the one field that may differ).
[[maybe_unused]] std::vector<nlohmann::json> records(const std::string& prefix, const fs::path& input, const std::string& init,
                                                     const fs::path& out) {
    const std::string command = prefix + std::string(RAYS_REPLAY) + " --input " + input.string() + " --init " + init +
                                " --budget-us 1000000 --out " + out.string() + " 2>/dev/null";
    REQUIRE(WEXITSTATUS(std::system(command.c_str())) == 0);
    std::ifstream in(out);
    std::vector<nlohmann::json> result;
    for (std::string line; std::getline(in, line);) {
        auto o = nlohmann::json::parse(line);
        o.erase("time_us");
        result.push_back(std::move(o));
    }
    return result;
}

}  // namespace

TEST_CASE("the frame kernels built for AVX2 and for any x86-64 give the same records", "[tools]") {
#if !defined(__x86_64__) || defined(__clang__)
    rays::test::skip("the frame kernels are built twice only on x86-64 with GCC");
#elif defined(RAYS_SANITIZED)
    rays::test::skip("not run under the sanitizers (their runtime under qemu-user is not what this checks); the Release build runs it");
#else
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2")) rays::test::skip("this CPU has no AVX2: the AVX2 build cannot run here to compare");
    if (std::system("command -v qemu-x86_64 >/dev/null 2>&1") != 0)
        rays::test::skip("qemu-x86_64 (Debian's qemu-user) is absent: no CPU without AVX2 to run the other build on");
    const rays::test::TempDir scratch;
    const fs::path colour = scratch.path() / "colour.y4m", grey = scratch.path() / "star.y4m";
    write_colour_scene(colour, 40);
    REQUIRE(WEXITSTATUS(std::system((std::string(RAYS_SCENE) + " --scene star --frames 40 --out " + grey.string() + " >/dev/null").c_str())) == 0);
    const std::string without_avx2 = "qemu-x86_64 -cpu Nehalem ";
    for (const auto& [input, init] : {std::pair{colour, std::string("40,64")}, std::pair{grey, std::string("auto")}}) {
        INFO(input.filename().string());
        const auto here = records("", input, init, scratch.path() / "here.jsonl");
        const auto emulated = records(without_avx2, input, init, scratch.path() / "emulated.jsonl");
        REQUIRE(here.size() == 41);  // the header and 40 frames
        int tracking = 0;
        for (const auto& o : here) tracking += o.value("state", "") == "tracking";
        CHECK(tracking >= 20);  // the kernels ran on tracked frames, not only on a search
        REQUIRE(emulated.size() == here.size());
        for (std::size_t k = 0; k < here.size(); ++k) {
            INFO("record " << k);
            CHECK(emulated[k] == here[k]);
        }
    }
#endif
}
