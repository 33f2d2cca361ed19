// Fuzz target: sprites. Seeds: synthetic_spr_seeds() plus the game's *.spr files.
#include "formats/spr.h"
#include "fuzz_target.h"
#include "support/synth_spr.h"

namespace {

// Reads every element of a parsed sprite so the sanitizers see any bad size.
uint64_t walk(const nq::Spr& spr) {
    uint64_t sum = 0;
    for (const auto& frame : spr.frames) {
        for (float f : frame.intervals) sum += f > 0;
        for (const auto& pic : frame.pictures) {
            // Address pixels by (x, y) as a renderer would, not just by the vector's size.
            for (int32_t y = 0; y < pic.height; ++y) {
                for (int32_t x = 0; x < pic.width; ++x) {
                    sum += pic.pixels.at(size_t(y) * size_t(pic.width) + size_t(x));
                }
            }
        }
    }
    sum += nq::sprite_type_name(spr.header.type)[0];
    for (const auto& w : spr.warnings) sum += w.size();
    return sum;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_spr_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto spr = nq::parse_spr({data, size}, "fuzz.spr");
    if (spr) {
        volatile uint64_t sink = walk(*spr);
        (void)sink;
    } else {
        volatile size_t sink = spr.error().to_string().size();
        (void)sink;
    }
    return 0;
}
