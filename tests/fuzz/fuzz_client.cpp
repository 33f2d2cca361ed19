// Demo bytes all the way through the client: container, decoder, client state (baselines,
// deltas, interpolation, temp entities, particles, beams), view and the visible-entity list —
// everything a downloaded demo can reach before the renderer.
#include <optional>

#include "client/demo_player.h"
#include "client/view.h"
#include "client/visible_entities.h"
#include "fuzz_target.h"
#include "support/synth_dem.h"

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_dem_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto player = nq::DemoPlayer::open({data, size}, "fuzz.dem", nq::DemoMode::TimeDemo);
    if (!player) return 0;
    nq::ClientState client;
    nq::ViewState view_state;
    nq::VisibleEntityList visible(1024);
    // Bounded: one block per frame, and a demo has at most as many frames as blocks.
    for (size_t frame = 0; frame <= player->block_count() + 1; ++frame) {
        if (player->run_frame(client, 1.0 / 72) == nq::FrameStatus::Ended) break;
        nq::ViewResult view = nq::compute_view(client, view_state);
        nq::collect_visible_entities(client, view, visible);
    }
    return 0;
}
