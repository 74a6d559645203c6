// SPDX-License-Identifier: Apache-2.0
// rays-replay end to end: a generated sequence in, JSON Lines and overlays out, errors as one line;
// and rays-soak's overlay folder and lockstep runs.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scenes/scene.hpp"
#include "support/temp_dir.hpp"

namespace fs = std::filesystem;

namespace {

// Where run() puts the command's standard error: a directory of this test process's own (CTest runs
// the test cases of this binary side by side), removed when it ends.
const rays::test::TempDir& scratch() {
    static const rays::test::TempDir dir;
    return dir;
}

fs::path error_file() { return scratch().path() / "stderr"; }

int run(const std::string& command) { return WEXITSTATUS(std::system((command + " 2>" + error_file().string()).c_str())); }

std::string last_error() {
    std::ifstream in(error_file());
    std::string line;
    std::getline(in, line);
    return line;
}

fs::path temp_dir(const char* name) {
    const fs::path dir = scratch().path() / name;
    fs::create_directories(dir);
    return dir;
}

}  // namespace

TEST_CASE("rays-replay tracks a generated sequence and writes the documented records", "[tools]") {
    const fs::path dir = temp_dir("replay");
    REQUIRE(run(std::string(RAYS_SCENE) + " --scene star --frames 60 --out " + (dir / "star.y4m").string()) == 0);
    REQUIRE(run(std::string(RAYS_REPLAY) + " --input " + (dir / "star.y4m").string() + " --out " + (dir / "run.jsonl").string() +
                " --overlay " + (dir / "ov").string() + " --crossings") == 0);
    std::ifstream in(dir / "run.jsonl");
    std::string line;
    REQUIRE(std::getline(in, line));
    const auto header = nlohmann::json::parse(line);
    CHECK(header["source"]["width"] == 128);
    CHECK(header["proc"]["width"] == 128);
    CHECK(header["scale"][0] == 1.0);
    CHECK(header["offset"][0] == 0.0);
    CHECK(header["config"].contains("rays.alpha"));
    auto scene = rays::scenes::make_scene("star");
    rays::scenes::SceneFrame truth;
    int frames = 0, tracking = 0;
    double iou = 0;
    while (std::getline(in, line)) {
        const auto o = nlohmann::json::parse(line);
        CHECK(o["frame"] == frames);
        if (o["state"] == "tracking") {
            ++tracking;
            std::vector<rays::Point> polygon;
            for (const auto& p : o["contour"]) polygon.push_back({p[0], p[1]});
            CHECK(o["rays"] == polygon.size());
            CHECK(o["ref"].is_array());
            scene->render(frames, truth);
            iou += rays::scenes::polygon_mask_iou(polygon, truth.mask);
        } else {
            CHECK(o["ref"].is_null());
            CHECK(o["contour"].empty());
        }
        ++frames;
    }
    CHECK(frames == 60);
    CHECK(tracking >= 55);
    CHECK(iou / tracking > 0.9);
    CHECK(fs::exists(dir / "ov" / "frame_00030.png"));
    fs::remove_all(dir);
}

TEST_CASE("rays-replay maps a cropped, non-square source as documented", "[tools]") {
    const fs::path dir = temp_dir("crop");
    {
        std::ofstream y4m(dir / "wide.y4m", std::ios::binary);
        y4m << "YUV4MPEG2 W320 H200 F25:1 Ip A1:1 Cmono\n";
        const std::vector<char> frame(320 * 200, 90);
        for (int i = 0; i < 3; ++i) y4m << "FRAME\n", y4m.write(frame.data(), static_cast<std::streamsize>(frame.size()));
    }
    REQUIRE(run(std::string(RAYS_REPLAY) + " --input " + (dir / "wide.y4m").string() + " --crop 20,10,256,160 --out " +
                (dir / "run.jsonl").string()) == 0);
    std::ifstream in(dir / "run.jsonl");
    std::string line;
    std::getline(in, line);
    const auto header = nlohmann::json::parse(line);
    CHECK(header["scale"][0] == Approx(2.0));
    CHECK(header["scale"][1] == Approx(1.25));
    CHECK(header["offset"][0] == Approx(20 + 0.5));
    CHECK(header["offset"][1] == Approx(10 + 0.125));
    fs::remove_all(dir);
}

TEST_CASE("rays-replay starts in a box given as --init X,Y,W,H", "[tools]") {
    const fs::path dir = temp_dir("box");
    REQUIRE(run(std::string(RAYS_SCENE) + " --scene disc --frames 5 --out " + (dir / "disc.y4m").string()) == 0);
    auto scene = rays::scenes::make_scene("disc");
    rays::scenes::SceneFrame truth;
    scene->render(0, truth);
    int x0 = rays::kFrameSize, y0 = rays::kFrameSize, x1 = -1, y1 = -1;  // the mask's bounding box
    for (int y = 0; y < rays::kFrameSize; ++y)
        for (int x = 0; x < rays::kFrameSize; ++x)
            if (truth.mask.at(x, y) > 127) x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    REQUIRE(x1 > x0);
    const std::string box = std::to_string(x0) + "," + std::to_string(y0) + "," + std::to_string(x1 - x0 + 1) + "," +
                            std::to_string(y1 - y0 + 1);
    REQUIRE(run(std::string(RAYS_REPLAY) + " --input " + (dir / "disc.y4m").string() + " --init " + box + " --out " +
                (dir / "run.jsonl").string()) == 0);
    std::ifstream in(dir / "run.jsonl");
    std::string line;
    REQUIRE(std::getline(in, line));  // the header
    REQUIRE(std::getline(in, line));
    const auto first = nlohmann::json::parse(line);
    INFO("box " << box);
    REQUIRE(first["state"] == "tracking");  // on the very first frame: no frame pair needed
    std::vector<rays::Point> polygon;
    for (const auto& p : first["contour"]) polygon.push_back({p[0], p[1]});
    CHECK(rays::scenes::polygon_mask_iou(polygon, truth.mask) >= 0.85);
    fs::remove_all(dir);
}

TEST_CASE("rays-replay says why a track was lost on the frame it was lost", "[tools]") {
    // A dark disc on grey for five frames, then grey alone: the target is gone.
    const fs::path dir = temp_dir("lost");
    for (int k = 0; k < 10; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "frame_%03d.pgm", k);
        std::ofstream out(dir / name, std::ios::binary);
        out << "P5\n128 128\n255\n";
        for (int y = 0; y < rays::kFrameSize; ++y)
            for (int x = 0; x < rays::kFrameSize; ++x)
                out.put(static_cast<char>(k < 5 && (x - 64) * (x - 64) + (y - 64) * (y - 64) <= 15 * 15 ? 40 : 160));
    }
    REQUIRE(run(std::string(RAYS_REPLAY) + " --input " + dir.string() + " --init 64,64 --out " + (dir / "run.jsonl").string()) == 0);
    std::ifstream in(dir / "run.jsonl");
    std::string line;
    REQUIRE(std::getline(in, line));  // the header
    int lost = 0, tracking = 0, sure = 0;
    while (std::getline(in, line)) {
        const auto o = nlohmann::json::parse(line);
        REQUIRE(o.contains("psr"));  // how surely the target's looks were found: 0 where not tracking
        // The frame a track is lost says why; the target is looked for again in it (attention.lost_frames
        // = 0): not found, the frame says "detecting".
        if (o.contains("lost_reason")) {
            ++lost;
            CHECK(!o["lost_reason"].get<std::string>().empty());
            CHECK(o["state"] == "detecting");
            CHECK(o["psr"] == 0);
        } else {
            CHECK(o["state"] != "lost");
            if (o["state"] == "tracking") ++tracking;
            if (o["state"] == "tracking" && o["psr"].get<double>() >= 5.0) ++sure;
        }
    }
    CHECK(tracking >= 5);
    CHECK(sure >= 3);  // the disc's frames after its first (nothing learned to look for yet)
    CHECK(lost >= 1);
    fs::remove_all(dir);
}

TEST_CASE("rays-replay names what is wrong with a malformed --init", "[tools]") {
    const std::string replay = std::string(RAYS_REPLAY) + " --input x --init ";
    CHECK(run(replay + "1,2,3") == 2);
    CHECK(last_error() == "rays-replay: --init wants auto, a point X,Y or a box X,Y,W,H in processing pixels, not '1,2,3'");
    CHECK(run(replay + "1,2,3,4,5") == 2);
    CHECK(last_error().find("X,Y,W,H") != std::string::npos);
    CHECK(run(replay + "10,10,-5,8") == 2);
    CHECK(last_error() == "rays-replay: --init X,Y,W,H: the box's width and height must be above 0, not '10,10,-5,8'");
    CHECK(run(replay + "10,10,5,0") == 2);
    CHECK(last_error().find("above 0") != std::string::npos);
    CHECK(run(replay + "100,10,40,8") == 2);
    CHECK(last_error().find("the box must lie inside the 128x128 processing frame") != std::string::npos);
    CHECK(run(replay + "-1,10,4,8") == 2);
    CHECK(last_error().find("inside") != std::string::npos);
    CHECK(run(replay + "500,3") == 2);
    CHECK(last_error().find("the point must lie in the processing frame") != std::string::npos);
    CHECK(run(replay + "1,2,a,4") == 2);
    CHECK(last_error().find("X,Y,W,H") != std::string::npos);
}

TEST_CASE("rays-replay refuses bad input with one line and a non-zero exit", "[tools]") {
    const fs::path dir = temp_dir("bad");
    CHECK(run(std::string(RAYS_REPLAY) + " --input " + (dir / "missing.y4m").string() + " --out /dev/null") != 0);
    CHECK(last_error().rfind("rays-replay: ", 0) == 0);
    {
        std::ofstream y4m(dir / "short.y4m", std::ios::binary);
        y4m << "YUV4MPEG2 W128 H128 F25:1 Cmono\nFRAME\n" << std::string(1000, 'x');
    }
    CHECK(run(std::string(RAYS_REPLAY) + " --input " + (dir / "short.y4m").string() + " --out /dev/null") == 1);
    CHECK(last_error().find("truncated") != std::string::npos);
    {
        std::ofstream y4m(dir / "bad.y4m", std::ios::binary);
        y4m << "NOTY4M W128\n";
    }
    CHECK(run(std::string(RAYS_REPLAY) + " --input " + (dir / "bad.y4m").string() + " --out /dev/null") == 1);
    CHECK(run(std::string(RAYS_REPLAY) + " --input x --init 500,3") == 2);
    CHECK(run(std::string(RAYS_REPLAY) + " --input x --crop 1,2,3") == 2);
    fs::remove_all(dir);
}

TEST_CASE("rays-soak --overlay makes its folder or fails once before the run", "[tools]") {
    const fs::path dir = temp_dir("soak") / "overlays" / "deep";
    REQUIRE(run(std::string(RAYS_SOAK) + " --frames 3 --overlay " + dir.string() + " >/dev/null") == 0);
    CHECK(fs::exists(dir / "frame-000000.png"));
    CHECK(fs::exists(dir / "frame-000002.png"));

    const fs::path blocked = temp_dir("soak-blocked") / "file";
    std::ofstream(blocked) << "a file, not a folder";
    CHECK(run(std::string(RAYS_SOAK) + " --frames 3 --overlay " + (blocked / "ov").string() + " >/dev/null") == 2);
    CHECK(last_error().rfind("rays-soak: --overlay: cannot create " + (blocked / "ov").string(), 0) == 0);
    std::ifstream in(error_file());
    std::string line;
    int lines = 0;
    while (std::getline(in, line)) ++lines;
    CHECK(lines == 1);
}

TEST_CASE("rays-soak --seeds runs each seed as --seed does and adds them up", "[tools]") {
    // Two seeds of a short lockstep run: each seed's row is that seed's own run, the totals their sum
    // and means.
    const std::string soak = std::string(RAYS_SOAK) + " --scenario soak-clutter --frames 120 --lockstep --json ";
    const fs::path dir = temp_dir("seeds");
    REQUIRE(run(soak + "--seeds 2-3 > " + (dir / "both.json").string()) == 0);
    REQUIRE(run(soak + "--seed 2 > " + (dir / "2.json").string()) == 0);
    REQUIRE(run(soak + "--seed 3 > " + (dir / "3.json").string()) == 0);
    auto read = [](const fs::path& path) {
        std::ifstream in(path);
        return nlohmann::json::parse(in);
    };
    const auto both = read(dir / "both.json"), two = read(dir / "2.json"), three = read(dir / "3.json");
    REQUIRE(both["seeds"].size() == 2);
    CHECK(both["seeds"][0] == two);
    CHECK(both["seeds"][1] == three);
    CHECK(both["seeds"][1]["config"]["seed"] == 3);
    CHECK(both["losses"] == two["losses"].get<long>() + three["losses"].get<long>());
    // The totals by cause (every cause named, 0 or not) count each run's losses by theirs.
    CHECK(both["loss_causes"].size() == 3);
    long by_cause = 0;
    for (const auto& [cause, count] : both["loss_causes"].items()) {
        long in_runs = 0;
        for (const auto& one : {two, three})
            for (const auto& c : one["loss_causes"]) in_runs += c == cause;
        CHECK(count == in_runs);
        by_cause += count.get<long>();
    }
    CHECK(by_cause == both["losses"]);
    CHECK(two["loss_causes"].size() == two["losses"]);
    CHECK(both["on_target_fraction"].get<double>() ==
          Approx((two["on_target_fraction"].get<double>() + three["on_target_fraction"].get<double>()) / 2));
    fs::remove_all(dir);
}

TEST_CASE("rays-soak --lockstep runs the same closed loop every time", "[tools]") {
    // Real time within a frame (the default) reaches the controller and the measured latency, so two
    // runs differ; in lockstep a run depends on its settings alone, frame by frame.
    const fs::path dir = temp_dir("lockstep");
    const std::string soak = std::string(RAYS_SOAK) + " --scenario soak-clutter --seed 3 --frames 150 --lockstep --trace ";
    REQUIRE(run(soak + (dir / "a.csv").string() + " >/dev/null") == 0);
    REQUIRE(run(soak + (dir / "b.csv").string() + " >/dev/null") == 0);
    auto read = [](const fs::path& path) {
        std::ifstream in(path);
        return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    };
    const std::string a = read(dir / "a.csv");
    CHECK(std::count(a.begin(), a.end(), '\n') == 151);  // the header and a row per frame
    CHECK(a == read(dir / "b.csv"));
    fs::remove_all(dir);
}
