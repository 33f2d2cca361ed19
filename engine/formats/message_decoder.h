// Decodes one server message buffer (one demo block, or one network packet) into the
// ServerMessage structs of server_message.h, for protocols 15, 666 and 999.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"
#include "formats/protocol.h"
#include "formats/server_message.h"

namespace nq {

// Where a message buffer came from, so errors point into the file.
struct MessageSource {
    std::string file;          // e.g. "demo1.dem"
    size_t block_index = 0;    // demo block number (0-based)
    uint64_t file_offset = 0;  // absolute file offset of the buffer's first byte
};

struct DecodedMessage {
    size_t offset = 0;  // offset of the message's first byte within the buffer
    size_t size = 0;    // bytes it occupies, svc byte included
    ServerMessage message;
};

struct DecodedBlock {
    std::vector<DecodedMessage> messages;
    std::vector<std::string> warnings;  // odd but decodable content
};

// Decodes every message in `buffer`. `state` carries the protocol and its flags from block to
// block: svc_serverinfo and svc_version change it (start a demo with the default, protocol 15,
// or with what the caller knows). An unknown svc number, an obsolete or illegible message, a
// malformed field, or a read past the buffer's end is an Error naming the block index, the
// absolute file offset and the message being decoded. On error `state` may have been updated
// by messages decoded before the failure.
Result<DecodedBlock> decode_server_message(std::span<const uint8_t> buffer,
                                           const MessageSource& source,
                                           protocol::ProtocolState& state);

}  // namespace nq
