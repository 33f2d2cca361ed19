// Fuzz target: saved games (Quake's text .sav). Seeds: synthetic_sav_seeds() plus any *.sav in
// the game data. Reads every parsed piece so the sanitizers see any bad size or index.
#include <string_view>

#include "fuzz_target.h"
#include "server/savegame.h"
#include "support/synth_sav.h"

namespace {

size_t walk(const nq::server::LoadedGame& game) {
    size_t sum = game.comment.size() + game.map.size() + size_t(game.skill);
    for (float parm : game.spawn_parms) sum += parm > 0;
    for (const std::string& style : game.lightstyles) sum += style.size();
    sum += game.time > 0;
    auto block = [&sum](const nq::server::SavedBlock& b) {
        sum += b.offset;
        for (const auto& pair : b.pairs) sum += pair.key.size() + pair.value.size() + pair.offset;
    };
    block(game.globals);
    for (const auto& edict : game.edicts) block(edict);
    return sum;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_sav_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto game = nq::server::read_savegame(text, "fuzz.sav");
    if (game) {
        volatile size_t sink = walk(*game);
        (void)sink;
    } else {
        volatile size_t sink = game.error().to_string().size();
        (void)sink;
    }
    return 0;
}
