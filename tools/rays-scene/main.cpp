// rays-scene: writes one of the generated scenes as YUV4MPEG2, with its masks and truth.
#include <cstdio>
#include <string>

#include "io/y4m_writer.hpp"
#include "scenes/scene.hpp"

namespace {

int usage_error(const std::string& message) {
    std::fprintf(stderr, "rays-scene: %s\nusage: rays-scene --list | --scene NAME --out SEQ.y4m [--masks MASKS.y4m] "
                         "[--truth GT.csv] [--frames N]\n", message.c_str());
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    std::string scene_name, out, masks, truth;
    int frames = -1;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--list") {
            for (auto name : rays::scenes::scene_names()) {
                auto s = rays::scenes::make_scene(name);
                std::printf("%-14.*s %4d frames  %.*s\n", static_cast<int>(name.size()), name.data(), s->frame_count(),
                            static_cast<int>(s->description().size()), s->description().data());
            }
            return 0;
        }
        if (i + 1 >= argc) return usage_error("option " + arg + " needs a value");
        const std::string value = argv[++i];
        if (arg == "--scene") scene_name = value;
        else if (arg == "--out") out = value;
        else if (arg == "--masks") masks = value;
        else if (arg == "--truth") truth = value;
        else if (arg == "--frames") {
            try {
                frames = std::stoi(value);
            } catch (...) {
                return usage_error("--frames wants a number, not '" + value + "'");
            }
        } else return usage_error("unknown option " + arg);
    }
    if (scene_name.empty() || out.empty()) return usage_error("--scene and --out are required");
    const auto scene = rays::scenes::make_scene(scene_name);
    if (!scene) return usage_error("unknown scene '" + scene_name + "' (see --list)");
    if (frames < 0 || frames > scene->frame_count()) frames = scene->frame_count();

    rays::io::Y4mWriter seq, mask_writer;
    if (!seq.open(out, rays::kFrameSize, rays::kFrameSize, 25, 1))
        return std::fprintf(stderr, "rays-scene: %s\n", seq.error().c_str()), 1;
    if (!masks.empty() && !mask_writer.open(masks, rays::kFrameSize, rays::kFrameSize, 25, 1))
        return std::fprintf(stderr, "rays-scene: %s\n", mask_writer.error().c_str()), 1;
    std::FILE* gt = truth.empty() ? nullptr : std::fopen(truth.c_str(), "w");
    if (!truth.empty() && !gt) return std::fprintf(stderr, "rays-scene: cannot write %s\n", truth.c_str()), 1;
    if (gt) std::fprintf(gt, "frame,cx,cy,area\n");
    rays::scenes::SceneFrame frame;
    for (int i = 0; i < frames; ++i) {
        scene->render(i, frame);
        if (!seq.write(frame.image.px.data()) || (!masks.empty() && !mask_writer.write(frame.mask.px.data())))
            return std::fprintf(stderr, "rays-scene: write failed\n"), 1;
        if (gt) std::fprintf(gt, "%d,%.3f,%.3f,%.2f\n", i, frame.truth.cx, frame.truth.cy, frame.truth.area);
    }
    if (gt && std::fclose(gt) != 0) return std::fprintf(stderr, "rays-scene: cannot finish %s\n", truth.c_str()), 1;
    std::fprintf(stderr, "rays-scene: wrote %d frames of '%s' to %s\n", frames, scene_name.c_str(), out.c_str());
    return 0;
}
