// SPDX-License-Identifier: Apache-2.0
// rays-scene: writes one of the generated scenes as mono YUV4MPEG2, with its masks and truth
// (gt.csv: frame,cx,cy,area, as in ../shared/devset). Bad arguments: one line on stderr, exit 2.
#include <charconv>
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

#include "io/stdio_file.hpp"
#include "io/y4m_writer.hpp"
#include "scenes/scene.hpp"

namespace {

constexpr const char* kUsage =
    "usage: rays-scene --list | --scene NAME --out SEQ.y4m [--masks MASKS.y4m] [--truth GT.csv] [--frames N]";

int usage_error(const std::string& message) {
    std::fprintf(stderr, "rays-scene: %s; %s\n", message.c_str(), kUsage);
    return 2;
}

int failure(const std::string& message) {
    std::fprintf(stderr, "rays-scene: %s\n", message.c_str());
    return 1;
}

void list_scenes() {
    for (const std::string_view name : rays::scenes::scene_names()) {
        const auto scene = rays::scenes::make_scene(name);
        std::printf("%-14.*s %4d frames  %.*s\n", static_cast<int>(name.size()), name.data(), scene->frame_count(),
                    static_cast<int>(scene->description().size()), scene->description().data());
    }
}

}  // namespace

int main(int argc, char** argv) {
    std::string scene_name, out, masks, truth;
    int frames = 0;  // 0: the whole scene
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--list") {
            list_scenes();
            return 0;
        }
        if (arg != "--scene" && arg != "--out" && arg != "--masks" && arg != "--truth" && arg != "--frames")
            return usage_error("unknown option '" + std::string(arg) + "'");
        if (i + 1 >= argc) return usage_error("option " + std::string(arg) + " needs a value");
        const std::string_view value = argv[++i];
        if (arg == "--scene") scene_name = value;
        else if (arg == "--out") out = value;
        else if (arg == "--masks") masks = value;
        else if (arg == "--truth") truth = value;
        else {
            const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), frames);
            if (error != std::errc{} || end != value.data() + value.size() || frames < 1)
                return usage_error("--frames wants a positive whole number, not '" + std::string(value) + "'");
        }
    }
    if (scene_name.empty() || out.empty()) return usage_error("--scene and --out are required");
    const auto scene = rays::scenes::make_scene(scene_name);
    if (!scene) return usage_error("unknown scene '" + scene_name + "' (see --list)");
    if (frames == 0 || frames > scene->frame_count()) frames = scene->frame_count();

    rays::io::Y4mWriter seq, mask_writer;
    if (!seq.open(out, rays::kFrameSize, rays::kFrameSize, 25, 1)) return failure(seq.error());
    if (!masks.empty() && !mask_writer.open(masks, rays::kFrameSize, rays::kFrameSize, 25, 1))
        return failure(mask_writer.error());
    rays::io::StdioFile gt(truth.empty() ? nullptr : std::fopen(truth.c_str(), "w"));
    if (!truth.empty() && !gt) return failure("cannot write " + truth);
    if (gt) std::fprintf(gt.get(), "frame,cx,cy,area\n");

    const auto frame = std::make_unique<rays::scenes::SceneFrame>();
    for (int i = 0; i < frames; ++i) {
        scene->render(i, *frame);
        if (!seq.write(frame->image.px.data())) return failure(seq.error());
        if (!masks.empty() && !mask_writer.write(frame->mask.px.data())) return failure(mask_writer.error());
        if (gt) std::fprintf(gt.get(), "%d,%.3f,%.3f,%.2f\n", i, frame->truth.cx, frame->truth.cy, frame->truth.area);
    }
    if (!seq.close()) return failure(seq.error());
    if (!masks.empty() && !mask_writer.close()) return failure(mask_writer.error());
    if (gt && std::fclose(gt.release()) != 0) return failure("cannot finish " + truth);
    std::fprintf(stderr, "rays-scene: wrote %d frames of '%s' to %s\n", frames, scene_name.c_str(), out.c_str());
    return 0;
}
