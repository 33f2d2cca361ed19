// Fuzz target for BSP maps: parse, then exercise every query on what parsed (PVS rows, hull
// contents, traces, entity text, .lit with the map's sample count) so sanitizers see bad data.
#include <algorithm>

#include "formats/bsp.h"
#include "formats/entities.h"
#include "fuzz_target.h"
#include "support/synth_bsp.h"

namespace {

// Bounds per input, so one execution stays fast on large maps.
constexpr uint32_t kMaxLeafsDecoded = 64;
constexpr size_t kMaxModelsProbed = 8;

volatile uint64_t g_sink;  // keeps the walks from being optimised away

void touch_textures(const nq::Bsp& bsp) {
    uint64_t sum = 0;
    for (const auto& t : bsp.textures) {
        for (const auto& mip : t.mips) {
            for (uint8_t p : mip.pixels) sum += p;
        }
    }
    g_sink = sum;
}

void probe_hulls(const nq::Bsp& bsp) {
    uint64_t sum = 0;
    for (size_t model = 0; model < std::min(bsp.models.size(), kMaxModelsProbed); ++model) {
        const auto& m = bsp.models[model];
        const nq::BspVec3 centre{(m.mins[0] + m.maxs[0]) / 2, (m.mins[1] + m.maxs[1]) / 2,
                                 (m.mins[2] + m.maxs[2]) / 2};
        for (int hull = 0; hull < 3; ++hull) {
            sum += static_cast<uint64_t>(nq::point_contents(bsp, hull, centre, model));
            sum += static_cast<uint64_t>(nq::point_contents(bsp, hull, m.mins, model));
            const auto tr = nq::trace_hull(bsp, hull, m.maxs, m.mins, model);
            sum += tr.hit() + tr.start_solid;
        }
        sum += nq::leaf_at(bsp, centre, model);
    }
    if (!bsp.models.empty()) sum += nq::trace_down(bsp, bsp.models[0].maxs, 8192).hit();
    g_sink = sum;
}

void decode_pvs(const nq::Bsp& bsp) {
    uint64_t sum = 0;
    const auto leafs = static_cast<uint32_t>(std::min<size_t>(bsp.leafs.size(), kMaxLeafsDecoded));
    for (uint32_t leaf = 0; leaf <= leafs; ++leaf) {
        const auto row = nq::decompress_vis(bsp, leaf);
        for (uint8_t b : row) sum += b;
        sum += nq::pvs_contains(row, leaf);
    }
    g_sink = sum;
}

void walk_entities(const nq::Bsp& bsp) {
    auto list = nq::parse_entities(bsp.entities, bsp.name, bsp.entities_offset);
    if (!list) return;
    uint64_t sum = 0;
    for (const auto& e : list->entities) {
        sum += nq::classname(e).size();
        sum += nq::find_vec3(e, "origin").has_value();
    }
    g_sink = sum;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_bsp_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto bsp = nq::parse_bsp({data, size}, "fuzz.bsp");
    if (!bsp) {
        // The same bytes as a .lit and as entity text: both parsers must cope with anything.
        (void)nq::parse_lit({data, size}, "fuzz.lit", size / 3);
        (void)nq::parse_entities(std::span<const uint8_t>(data, size), "fuzz.ent");
        return 0;
    }
    touch_textures(*bsp);
    probe_hulls(*bsp);
    decode_pvs(*bsp);
    walk_entities(*bsp);
    return 0;
}
