// Synthetic demos and server messages for tests and fuzz seeds, built with our own encoder.
// Every float value handed out lies on the protocol's grid, computed here from the documented
// encodings (not by round-tripping through the code under test).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/protocol.h"
#include "formats/server_message.h"
#include "support/seed_file.h"

namespace nq::test {

// Representable coordinate / angle values for the encoding that `state` selects.
std::vector<float> grid_coords(const protocol::ProtocolState& state);
std::vector<float> grid_angles(const protocol::ProtocolState& state);

// Every RMQ flag word made of the coordinate and angle flags (all 2^5 subsets), each also
// with PRFL_EDICTSCALE added when `with_scale` is true.
std::vector<uint32_t> rmq_flag_combinations(bool with_scale = false);

// A message stream that starts with an svc_serverinfo for `state` and then holds every message
// kind the protocol allows (FitzQuake kinds only for 666/999), every temp-entity type, and
// clientdata / entity updates / sounds / baselines whose bit masks together set every bit.
std::vector<ServerMessage> every_message_kind(const protocol::ProtocolState& state);

// Encodes each inner list as one demo block (view angles 1, 2, 3 degrees times the block
// number) after the CD track line. The stream starts in `initial`. Throws std::runtime_error
// if the encoder refuses a message (a bug in the caller's test data).
std::vector<uint8_t> build_demo(const std::vector<std::vector<ServerMessage>>& blocks,
                                protocol::ProtocolState initial = {},
                                const std::string& cd_track_line = "-1");

// A demo whose blocks hold the given raw message bytes (for malformed-message tests).
std::vector<uint8_t> build_raw_demo(const std::vector<std::vector<uint8_t>>& messages,
                                    const std::string& cd_track_line = "-1");

// Small demos for protocols 15, 666 and 999 under many flag combinations, plus a demo cut
// in its last block.
std::vector<SeedFile> synthetic_dem_seeds();

}  // namespace nq::test
