// Fuzz target: the obscurance scene files vo_dump_scene writes and vo_reference reads
// (nprlib/obscurance/scene_file.h). Seeds: scenes encoded here (empty, one triangle of each
// kind, a few), and one cut short.
#include <string>

#include "fuzz_target.h"
#include "obscurance/scene_file.h"

namespace {

std::vector<nq::test::SeedFile> scene_seeds() {
    using nq::npr::obscurance::ObscuranceScene;
    ObscuranceScene scene;
    scene.width = 64;
    scene.height = 48;
    for (int i = 0; i < 16; ++i) scene.projection[i] = (i % 5 == 0) ? 1.0f : 0.0f;
    std::vector<nq::test::SeedFile> seeds{{"empty.bin", encode_scene(scene)}};
    scene.triangles.push_back({{0, 0, -10}, {1, 0, -10}, {0, 1, -10}, true});
    scene.triangles.push_back({{0, 0, -20}, {5, 0, -20}, {0, 5, -30}, false});
    seeds.push_back({"two.bin", encode_scene(scene)});
    std::vector<uint8_t> cut = encode_scene(scene);
    cut.resize(cut.size() - 7);
    seeds.push_back({"cut.bin", cut});
    return seeds;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, scene_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto parsed = nq::npr::obscurance::parse_scene({data, size}, "fuzz.bin");
    float sum = 0.0f;
    if (parsed.scene) {
        for (const auto& t : parsed.scene->triangles) sum += t.a.x + t.b.y + t.c.z + float(t.solid);
        sum += parsed.scene->projection[0] + float(parsed.scene->width + parsed.scene->height);
    }
    volatile size_t keep = parsed.error.size() + size_t(sum != sum);
    (void)keep;
    return 0;
}
