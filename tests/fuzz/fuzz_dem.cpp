// Fuzz target for demos: the container, every block through the message decoder (carrying the
// protocol state as a player would), the summary, and a round-trip oracle: whatever decoded
// and then encoded must decode again to the very same messages.
#include <algorithm>
#include <cstdlib>
#include <variant>

#include "formats/demo_summary.h"
#include "formats/message_encoder.h"
#include "fuzz_target.h"
#include "support/synth_dem.h"

namespace {

// Re-decodes `bytes` from `state` and requires exactly `expected`.
void check_round_trip(const std::vector<uint8_t>& bytes, nq::protocol::ProtocolState state,
                      const std::vector<nq::ServerMessage>& expected) {
    auto again = nq::decode_server_message(bytes, {"fuzz.dem", 0, 0}, state);
    if (!again || again->messages.size() != expected.size()) std::abort();
    for (size_t i = 0; i < expected.size(); ++i) {
        if (!(again->messages[i].message == expected[i])) std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_dem_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto decoded = nq::decode_demo({data, size}, "fuzz.dem");
    if (!decoded) return 0;
    nq::protocol::ProtocolState state;
    // The oracle costs two more passes; on the big real demos it runs on their first blocks
    // only (every block is still decoded above), so more mutations fit in a fuzzing run.
    const size_t oracle_blocks = std::min<size_t>(decoded->blocks.size(), 256);
    for (size_t b = 0; b < oracle_blocks; ++b) {
        std::vector<nq::ServerMessage> messages;
        for (const auto& m : decoded->blocks[b].messages) messages.push_back(m.message);
        const nq::protocol::ProtocolState before = state;
        // The encoder may refuse what the decoder tolerates (e.g. FitzQuake messages under
        // protocol 15), but what it accepts must decode again unchanged.
        auto bytes = nq::encode_server_messages(messages, state);
        if (bytes) {
            check_round_trip(bytes.value(), before, messages);
        } else {  // resynchronise the state from the original block
            state = before;
            (void)nq::decode_server_message(decoded->demo.blocks[b].message, {"fuzz.dem", b, 0},
                                            state);
        }
    }
    nq::DemoSummary summary = nq::summarize_demo(decoded.value(), "fuzz.dem");
    if (summary.blocks != decoded->demo.blocks.size()) std::abort();
    return 0;
}
