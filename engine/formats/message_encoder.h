// Encodes ServerMessage structs (server_message.h) back into protocol 15 / 666 / 999 bytes:
// for round-trip tests now, for recording demos later. Quantisation is the protocol's own, so
// decode(encode(x)) == x for every value already on the protocol's grid (i.e. any decoded
// value). Values that the protocol cannot carry (out of range, a field whose bit is clear but
// whose value is not the default, a FitzQuake message under protocol 15, ...) are errors,
// never silently altered.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "common/result.h"
#include "formats/protocol.h"
#include "formats/server_message.h"

namespace nq {

// Appends the encoding of `messages` to a new buffer. `state` is the stream's protocol and
// flags; ServerInfo and Version messages switch it, exactly as the decoder does. Errors name
// the message's index and kind; their offset is the buffer offset where it would have started
// and their file is "<encoder>". On error `state` may already reflect messages before it.
Result<std::vector<uint8_t>> encode_server_messages(std::span<const ServerMessage> messages,
                                                    protocol::ProtocolState& state);

}  // namespace nq
