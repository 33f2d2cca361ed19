// Decodes one server message buffer (one demo block, or one network packet) into the
// ServerMessage structs of server_message.h, for protocols 15, 666 and 999.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "common/byte_reader.h"
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

// The same decoding for a reader of many blocks of one file (a demo player, a block per frame):
// the block is decoded into storage kept from call to call. Once its vectors have grown to the
// largest block, decoding allocates only for the text a message carries (print, centerprint,
// stufftext, finale, lightstyle patterns, names, precache lists) when it is longer than a
// std::string holds in place, and for errors and warnings.
class ServerMessageDecoder {
  public:
    explicit ServerMessageDecoder(std::string file);

    // Decodes `buffer` (block `block_index`, whose first byte is at `file_offset`) into block();
    // nullopt on success, else the Error decode_server_message would return. On error, block()
    // holds the messages decoded before it.
    std::optional<Error> decode(std::span<const uint8_t> buffer, size_t block_index,
                                uint64_t file_offset, protocol::ProtocolState& state);

    // The last block decoded; valid until the next decode(). Mutable so that warnings can be
    // moved out.
    DecodedBlock& block() { return block_; }
    const DecodedBlock& block() const { return block_; }

  private:
    ByteReader reader_;
    DecodedBlock block_;
};

}  // namespace nq
