// The Quake demo (.dem) container: a text line with the forced CD track ("-1\n"), then blocks
// of { int32 message length, float32 view angles[3], message bytes }. Each block holds one
// server message as the client received it (decode it with message_decoder.h).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

// Larger than any engine's message buffer (64000 in FitzQuake-family engines); a length beyond
// it is a lying length, not a big message.
inline constexpr int32_t kMaxDemoMessageBytes = 65536 * 4;
inline constexpr size_t kDemoBlockHeaderBytes = 16;  // int32 length + 3 float angles
inline constexpr size_t kMaxCdTrackLineBytes = 32;   // the line is an integer; real ones are short

struct DemoBlock {
    uint64_t offset = 0;                 // absolute offset of the block header in the file
    std::array<float, 3> view_angles{};  // the client's view angles when the block was recorded
    std::vector<uint8_t> message;
    // Absolute file offset of message[0] (errors in a message point into the file).
    uint64_t message_offset() const { return offset + kDemoBlockHeaderBytes; }
    bool operator==(const DemoBlock&) const = default;
};

struct Demo {
    std::string cd_track_line;  // the first line without its '\n', e.g. "-1"
    int cd_track = -1;          // its value; -1 when not an integer (see warnings)
    std::vector<DemoBlock> blocks;
    std::vector<std::string> warnings;
};

struct DemParseOptions {
    // Real demos often end mid-block (the recording was cut); by default that is a warning
    // and parsing stops there. Set to false to make it an error instead.
    bool allow_truncated_tail = true;
};

Result<Demo> parse_dem(std::span<const uint8_t> data, const std::string& name,
                       const DemParseOptions& options = {});

// Serialises a demo (blocks' `offset` is ignored; it is recomputed on parsing).
std::vector<uint8_t> write_dem(const Demo& demo);

}  // namespace nq
