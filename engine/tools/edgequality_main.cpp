// edgequality: how well a style's lines follow the silhouettes of an object-id reference, and
// how much they flicker (engine/quality/edge_quality.h has the rules).
//   edgequality silhouettes REFERENCE.png DRAWN.png [--json]
//   edgequality flicker REFERENCE.png DRAWN.png REFERENCE.png DRAWN.png ... [--json]
// Options may come before or after the files. Exit status: 0, 1 when an image cannot be read
// or the sizes differ, 2 on a bad command line.
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "common/json_writer.h"
#include "quality/edge_quality.h"

namespace {

using namespace nq;

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

int usage(FILE* to, int status) {
    std::fprintf(
        to,
        "usage: edgequality silhouettes REFERENCE.png DRAWN.png [--json]\n"
        "       edgequality flicker REFERENCE.png DRAWN.png [REFERENCE.png DRAWN.png ...] "
        "[--json]\n"
        "  REFERENCE: the technical style's object-id picture (tech_shading 3) of a frame;\n"
        "  DRAWN: the same frame as the style draws it. Lines are DRAWN's pure black\n"
        "  pixels that are not black in REFERENCE.\n"
        "  silhouettes: recall (outline pixels with a line within 1 px), precision (line\n"
        "  pixels within 2 px of an outline), on_models (within 2 px of a model).\n"
        "  flicker: over consecutive frames, the share of line pixels that appear or\n"
        "  vanish, against the same for the reference's outlines.\n");
    return status;
}

struct Options {
    std::string command;
    std::vector<std::string> files;
    bool json = false;
};

bool parse(int argc, char** argv, Options& o, bool& help) {
    for (int i = 1; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--help" || arg == "-h") {
            help = true;
        } else if (arg == "--json") {
            o.json = true;
        } else if (arg.starts_with("-")) {
            return false;
        } else if (o.command.empty()) {
            o.command = arg;
        } else {
            o.files.emplace_back(arg);
        }
    }
    if (help) return true;
    if (o.command == "silhouettes") return o.files.size() == 2;
    if (o.command == "flicker") return o.files.size() >= 4 && o.files.size() % 2 == 0;
    return false;
}

// Reads every file; false (and a message naming the file) when one cannot be read or the sizes
// differ.
bool read_images(const std::vector<std::string>& files, std::vector<RgbImage>& out) {
    for (const std::string& path : files) {
        Result<RgbImage> image = read_png(path);
        if (!image) {
            std::fprintf(stderr, "edgequality: %s\n", image.error().to_string().c_str());
            return false;
        }
        if (!out.empty() && (image->width != out[0].width || image->height != out[0].height)) {
            std::fprintf(stderr, "edgequality: %s: %dx%d, but %s is %dx%d\n", path.c_str(),
                         image->width, image->height, files[0].c_str(), out[0].width,
                         out[0].height);
            return false;
        }
        out.push_back(std::move(*image));
    }
    return true;
}

void print_silhouettes(const quality::SilhouetteScore& s, bool json) {
    if (json) {
        JsonWriter w;
        w.begin_object()
            .field("recall", s.recall)
            .field("precision", s.precision)
            .field("on_models", s.on_models)
            .field("outline_pixels", uint64_t{s.outline_pixels})
            .field("line_pixels", uint64_t{s.line_pixels})
            .end_object();
        std::printf("%s\n", w.str().c_str());
        return;
    }
    std::printf(
        "recall %.4f  precision %.4f  on_models %.4f  (%zu outline pixels, %zu line pixels)\n",
        s.recall, s.precision, s.on_models, s.outline_pixels, s.line_pixels);
}

void print_flicker(const quality::FlickerScore& f, bool json) {
    if (json) {
        JsonWriter w;
        w.begin_object()
            .field("frames", uint64_t{f.frames})
            .field("lines", f.lines)
            .field("outlines", f.outlines)
            .field("excess", f.excess)
            .end_object();
        std::printf("%s\n", w.str().c_str());
        return;
    }
    std::printf("lines change %.4f  outlines change %.4f  excess %.4f  (%zu frames)\n", f.lines,
                f.outlines, f.excess, f.frames);
}

}  // namespace

int main(int argc, char** argv) {
    Options o;
    bool help = false;
    if (!parse(argc, argv, o, help)) return usage(stderr, kExitUsage);
    if (help) return usage(stdout, kExitOk);
    std::vector<RgbImage> images;
    if (!read_images(o.files, images)) return kExitError;
    if (o.command == "silhouettes") {
        print_silhouettes(quality::score_silhouettes(images[0], images[1]), o.json);
        return kExitOk;
    }
    std::vector<RgbImage> references, drawn;
    for (size_t i = 0; i < images.size(); i += 2) {
        references.push_back(std::move(images[i]));
        drawn.push_back(std::move(images[i + 1]));
    }
    print_flicker(quality::score_flicker(references, drawn), o.json);
    return kExitOk;
}
