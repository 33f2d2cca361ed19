// Fuzz target: alias models. Seeds: synthetic_mdl_seeds() plus the game's *.mdl files.
#include "formats/mdl.h"
#include "fuzz_target.h"
#include "support/synth_mdl.h"

namespace {

// Reads every element of a parsed model so the sanitizers see any bad size or index.
uint64_t walk(const nq::Mdl& mdl) {
    uint64_t sum = 0;
    for (const auto& skin : mdl.skins) {
        for (float f : skin.intervals) sum += f > 0;
        for (const auto& image : skin.images) {
            for (uint8_t p : image) sum += p;
        }
    }
    for (const auto& st : mdl.tex_coords) sum += uint32_t(st.s) + uint32_t(st.t);
    for (const auto& tri : mdl.triangles) {
        // Index the per-vertex tables through the triangles, as a renderer would.
        for (int32_t v : tri.vertices) sum += uint32_t(mdl.tex_coords.at(size_t(v)).on_seam);
    }
    for (const auto& frame : mdl.frames) {
        for (float f : frame.intervals) sum += f > 0;
        for (const auto& pose : frame.poses) {
            sum += pose.name.size();
            for (const nq::Vec3& p : nq::decoded_positions(mdl.header, pose)) sum += p[0] > 0;
            for (const auto& tv : pose.vertices) sum += tv.light_normal_index;
        }
    }
    const nq::Bounds b = nq::decoded_frame_bounds(mdl);
    sum += b.min[0] <= b.max[0];
    sum += nq::mdl_flag_names(mdl.header.flags).size();
    for (const auto& w : mdl.warnings) sum += w.size();
    return sum;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_mdl_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto mdl = nq::parse_mdl({data, size}, "fuzz.mdl");
    if (mdl) {
        volatile uint64_t sink = walk(*mdl);
        (void)sink;
    } else {
        volatile size_t sink = mdl.error().to_string().size();
        (void)sink;
    }
    return 0;
}
