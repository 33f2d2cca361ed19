// A pass over a whole demo: decode every block (decode_demo) and condense it into what
// `demotool info` prints (summarize_demo).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"
#include "formats/dem.h"
#include "formats/message_decoder.h"
#include "formats/protocol.h"

namespace nq {

struct DecodedDemo {
    Demo demo;                            // the container (its warnings included)
    std::vector<DecodedBlock> blocks;     // one per demo.blocks entry
    protocol::ProtocolState final_state;  // protocol and flags after the last block
};

// Parses the container and decodes every block, carrying the protocol state from block to
// block starting at `initial` (protocol 15 unless the caller knows better; a demo's own
// svc_serverinfo sets it). The first decode error is returned (it names block and offset).
Result<DecodedDemo> decode_demo(std::span<const uint8_t> data, const std::string& name,
                                protocol::ProtocolState initial = {});

struct MessageKindStats {
    int kind = 0;      // svc number, or kEntityUpdateKind
    std::string name;  // "svc_time", "entity_update"
    size_t count = 0;
    size_t bytes = 0;  // svc byte included
};

struct DemoSummary {
    std::string file;
    std::string cd_track_line;
    int cd_track = -1;
    bool has_server_info = false;
    int protocol = protocol::kNetQuake;  // from the first svc_serverinfo
    uint32_t protocol_flags = 0;
    std::string map;                  // first model of the first serverinfo, e.g. "maps/start.bsp"
    std::string level_name;           // the first serverinfo's level name ("the Introduction")
    std::vector<std::string> models;  // the first serverinfo's precache lists
    std::vector<std::string> sounds;
    std::vector<std::string> maps;  // the world model of every serverinfo, in order
    size_t blocks = 0;              // blocks in the file; each is one recorded frame
    size_t messages = 0;
    size_t message_bytes = 0;
    size_t entity_updates = 0;  // fast entity updates over the whole demo
    size_t time_messages = 0;
    std::optional<float> first_time;  // first and last svc_time value
    std::optional<float> last_time;
    // Duration of the demo, defined as the last svc_time value: the server clock of the last
    // recorded frame. The server clock starts near zero when a map loads, so for a demo
    // recorded from a map's start this is its playing time. 0 when there is no svc_time.
    float duration = 0;
    // Sum over map segments (split at each svc_serverinfo) of last minus first svc_time: how
    // long the recording plays, also across map changes and for demos started mid-level.
    float playback_time = 0;
    std::vector<MessageKindStats> histogram;  // every kind seen, in kind order
    std::vector<std::string> warnings;        // container and decoder warnings
};

DemoSummary summarize_demo(const DecodedDemo& decoded, const std::string& name);

// Both steps at once.
Result<DemoSummary> summarize_demo_file(std::span<const uint8_t> data, const std::string& name,
                                        protocol::ProtocolState initial = {});

}  // namespace nq
