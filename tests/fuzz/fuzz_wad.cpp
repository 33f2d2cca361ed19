// Fuzz target: WAD2 archives and the loose .lmp formats. Every input is tried as a WAD (each
// lump then decoded as a picture or palette), and as a qpic, a palette, a colormap and a raw
// console font. Seeds: synthetic_wad_seeds() plus the game's *.wad and *.lmp files.
#include <algorithm>

#include "formats/lmp.h"
#include "formats/palette.h"
#include "formats/wad.h"
#include "fuzz_target.h"
#include "support/synth_wad.h"

namespace {

uint64_t walk_pic(const nq::Result<nq::Pic>& pic) {
    if (!pic) return pic.error().message.size();
    uint64_t sum = 0;
    for (int32_t y = 0; y < pic->height; ++y) {
        for (int32_t x = 0; x < pic->width; ++x) sum += pic->at(x, y);
    }
    return sum + pic->warnings.size();
}

// Entries may all point at the same bytes, so decoding every lump of a mutated directory costs
// lumps x file size; the first few hundred exercise the decoders just as well.
constexpr size_t kMaxLumpsDecoded = 256;

uint64_t walk_wad(const nq::Wad& wad) {
    uint64_t sum = wad.warnings.size();
    const size_t count = std::min(wad.lumps.size(), kMaxLumpsDecoded);
    for (size_t i = 0; i < count; ++i) {
        const nq::WadLump& lump = wad.lumps[i];
        sum += wad.find(lump.name) != nullptr;
        if (lump.type == uint8_t(nq::WadLumpType::Palette)) {
            if (auto bytes = wad.lump_bytes(lump)) {
                if (auto pal = nq::parse_palette(*bytes, "lump")) sum += pal->colors[255].r;
            }
        } else {
            sum += walk_pic(nq::parse_wad_pic(wad, lump));
        }
    }
    return sum;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_wad_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::span<const uint8_t> input(data, size);
    uint64_t sum = 0;
    if (auto wad = nq::parse_wad(input, "fuzz.wad")) sum += walk_wad(*wad);
    sum += walk_pic(nq::parse_qpic(input, "fuzz.lmp"));
    sum += walk_pic(nq::parse_conchars(input, "conchars"));
    if (auto pal = nq::parse_palette(input, "palette.lmp")) sum += pal->colors[0].g;
    if (auto map = nq::parse_colormap(input, "colormap.lmp")) {
        for (int level = 0; level < nq::kColormapLevels; ++level) sum += map->shade(level, 255);
    }
    volatile uint64_t sink = sum;
    (void)sink;
    return 0;
}
