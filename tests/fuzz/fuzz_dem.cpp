// Fuzz target for demos: the container, every block through the message decoder (carrying the
// protocol state as a player would), the summary, and two oracles: whatever decoded and then
// encoded must decode again to the very same messages, and the reusing decoder the demo player
// runs must agree with the one-shot decoder, errors included.
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

// One block through both decoders: the same state, messages, warnings, or the same error.
// Returns false after an error (the player stops there).
bool same_decoding(nq::ServerMessageDecoder& decoder, const nq::DemoBlock& block, size_t index,
                   nq::protocol::ProtocolState& reused, nq::protocol::ProtocolState& one_shot) {
    auto error = decoder.decode(block.message, index, block.message_offset(), reused);
    auto expected = nq::decode_server_message(
        block.message, {"fuzz.dem", index, block.message_offset()}, one_shot);
    if (!(reused == one_shot)) std::abort();
    if (!expected) {
        if (!error || error->to_string() != expected.error().to_string()) std::abort();
        return false;
    }
    const nq::DecodedBlock& got = decoder.block();
    if (error || got.warnings != expected->warnings) std::abort();
    if (got.messages.size() != expected->messages.size()) std::abort();
    for (size_t i = 0; i < got.messages.size(); ++i) {
        const nq::DecodedMessage& a = got.messages[i];
        const nq::DecodedMessage& b = expected->messages[i];
        if (!(a.message == b.message) || a.offset != b.offset || a.size != b.size) std::abort();
    }
    return true;
}

// The player's reusing decoder over the first blocks (the later ones cost time, not coverage).
void check_reusing_decoder(const nq::Demo& demo) {
    nq::ServerMessageDecoder decoder("fuzz.dem");
    nq::protocol::ProtocolState reused, one_shot;
    const size_t blocks = std::min<size_t>(demo.blocks.size(), 256);
    for (size_t b = 0; b < blocks; ++b) {
        if (!same_decoding(decoder, demo.blocks[b], b, reused, one_shot)) return;
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    nq::fuzz::handle_write_seeds(*argc, *argv, nq::test::synthetic_dem_seeds());
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (auto demo = nq::parse_dem({data, size}, "fuzz.dem")) check_reusing_decoder(demo.value());
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
