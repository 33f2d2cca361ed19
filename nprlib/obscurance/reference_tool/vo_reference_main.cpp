// vo_reference SCENE OUT.png [--radius R] [--directions-per-side K] [--threads N]
//
// The ray-traced volumetric obscurance of the frame `vo_dump_scene SCENE` wrote (the engine's
// console), as a grey PNG the size of the viewport (255 = open), to compare with the engine's
// `vo_show 1` screenshot of the same frame (demos/bench_obscurance.sh does).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "obscurance/scene_file.h"
#include "raytraced_obscurance.h"
#include "video/png_io.h"

namespace {

constexpr const char* kUsage =
    "usage: vo_reference SCENE OUT.png [--radius R] [--directions-per-side K] [--threads N]\n"
    "  SCENE: a frame's geometry as the engine's vo_dump_scene writes it; OUT.png: its\n"
    "  ray-traced volumetric obscurance (grey, 255 = open). Options may come anywhere.\n";

int usage() {
    std::fputs(kUsage, stderr);
    return 2;
}

bool parse_number(const char* text, double lo, double hi, double& out) {
    char* end = nullptr;
    out = std::strtod(text, &end);
    return end != text && *end == '\0' && out >= lo && out <= hi;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace nq::npr::obscurance;
    std::vector<std::string> files;
    RaytraceOptions options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (arg.rfind("--", 0) != 0) {
            files.push_back(arg);
            continue;
        }
        double value = 0.0;
        const char* text = i + 1 < argc ? argv[++i] : "";
        if (arg == "--radius" && parse_number(text, 0.01, 4096.0, value)) {
            options.radius = float(value);
        } else if (arg == "--directions-per-side" && parse_number(text, 1, 256, value)) {
            options.directions_per_side = int(value);
        } else if (arg == "--threads" && parse_number(text, 0, 1024, value)) {
            options.threads = int(value);
        } else {
            std::fprintf(stderr, "vo_reference: bad option %s %s\n", arg.c_str(), text);
            return usage();
        }
    }
    if (files.size() != 2) return usage();
    const std::string scene_path = files[0], out_path = files[1];
    std::ifstream in(scene_path, std::ios::binary);
    if (!in) {
        std::fprintf(stderr, "vo_reference: cannot read %s\n", scene_path.c_str());
        return 1;
    }
    const std::vector<uint8_t> bytes((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
    const SceneParse parsed = parse_scene(bytes, scene_path);
    if (!parsed.scene) {
        std::fprintf(stderr, "vo_reference: %s\n", parsed.error.c_str());
        return 1;
    }
    const ObscuranceScene& scene = *parsed.scene;
    const RaytraceResult traced = raytrace_obscurance(scene, options);
    if (!traced.error.empty()) {
        std::fprintf(stderr, "vo_reference: %s\n", traced.error.c_str());
        return 1;
    }
    std::vector<uint8_t> rgb(size_t(scene.width) * scene.height * 3);
    for (uint32_t row = 0; row < scene.height; ++row) {
        const uint32_t y = scene.height - 1 - row;  // PNG rows top first
        for (uint32_t x = 0; x < scene.width; ++x) {
            const float open = traced.open[size_t(y) * scene.width + x];
            const auto grey = uint8_t(std::lround(std::clamp(open, 0.0f, 1.0f) * 255.0f));
            std::fill_n(rgb.begin() + std::ptrdiff_t((size_t(row) * scene.width + x) * 3), 3, grey);
        }
    }
    const std::string error = nq::write_png(out_path, int(scene.width), int(scene.height), rgb);
    if (!error.empty()) {
        std::fprintf(stderr, "vo_reference: %s\n", error.c_str());
        return 1;
    }
    std::printf("vo_reference: wrote %s (%ux%u, %zu triangles)\n", out_path.c_str(), scene.width,
                scene.height, scene.triangles.size());
    return 0;
}
