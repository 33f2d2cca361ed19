#include "formats/dem.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <optional>

#include "common/byte_reader.h"

namespace nq {
namespace {

// Parses "-1", "2", "+3"; nullopt for anything else (empty, letters, overflow).
std::optional<int> parse_track_number(const std::string& line) {
    size_t i = 0;
    bool negative = false;
    if (i < line.size() && (line[i] == '-' || line[i] == '+')) negative = line[i++] == '-';
    if (i == line.size()) return std::nullopt;
    int64_t value = 0;
    for (; i < line.size(); ++i) {
        if (line[i] < '0' || line[i] > '9') return std::nullopt;
        value = value * 10 + (line[i] - '0');
        if (value > 1'000'000'000) return std::nullopt;
    }
    return static_cast<int>(negative ? -value : value);
}

// The CD track line: up to the first '\n'. Engines tolerate a '\r' before it.
void read_cd_track_line(ByteReader& r, Demo& demo) {
    if (r.at_end()) r.fail("empty file: expected a CD track line");
    size_t limit = std::min(r.remaining(), kMaxCdTrackLineBytes + 1);
    auto head = r.bytes(limit);
    const uint8_t* nl = static_cast<const uint8_t*>(std::memchr(head.data(), '\n', head.size()));
    if (nl == nullptr) {
        r.fail_at(0,
                  "no CD track line: expected a short text line ending in '\\n' within the "
                  "first " +
                      std::to_string(kMaxCdTrackLineBytes + 1) + " bytes");
    }
    size_t len = static_cast<size_t>(nl - head.data());
    demo.cd_track_line.assign(reinterpret_cast<const char*>(head.data()), len);
    if (!demo.cd_track_line.empty() && demo.cd_track_line.back() == '\r') {
        demo.cd_track_line.pop_back();
    }
    r.seek(len + 1);
    if (auto track = parse_track_number(demo.cd_track_line)) {
        demo.cd_track = *track;
    } else {
        demo.warnings.push_back("CD track line \"" + demo.cd_track_line +
                                "\" is not an integer; using -1");
    }
}

std::string block_label(size_t index, size_t offset) {
    return "block " + std::to_string(index) + " (offset " + std::to_string(offset) + ")";
}

// Either records a warning and returns false (stop parsing), or throws when strict.
bool truncated_tail(const ByteReader& r, Demo& demo, const DemParseOptions& options, size_t index,
                    size_t start, const std::string& what) {
    std::string message = block_label(index, start) + ": " + what;
    if (!options.allow_truncated_tail) r.fail_at(start, message);
    demo.warnings.push_back(message + "; demo ends here (truncated recording)");
    return false;
}

// Reads one block; returns false when the data ends (cleanly or in a truncated block).
bool read_block(ByteReader& r, Demo& demo, const DemParseOptions& options) {
    if (r.at_end()) return false;
    size_t index = demo.blocks.size();
    size_t start = r.tell();
    if (r.remaining() < kDemoBlockHeaderBytes) {
        return truncated_tail(r, demo, options, index, start,
                              "block header truncated (" + std::to_string(r.remaining()) + " of " +
                                  std::to_string(kDemoBlockHeaderBytes) + " bytes)");
    }
    int32_t length = r.i32();
    if (length < 0 || length > kMaxDemoMessageBytes) {
        r.fail_at(start, block_label(index, start) + ": message length " + std::to_string(length) +
                             " is outside 0.." + std::to_string(kMaxDemoMessageBytes));
    }
    DemoBlock block;
    block.offset = r.absolute(start);
    for (float& a : block.view_angles) {
        a = r.f32();
        if (!std::isfinite(a)) {
            r.fail_at(r.tell() - 4, block_label(index, start) + ": view angle is NaN or infinite");
        }
    }
    if (static_cast<size_t>(length) > r.remaining()) {
        return truncated_tail(r, demo, options, index, start,
                              "message of " + std::to_string(length) + " bytes truncated to " +
                                  std::to_string(r.remaining()));
    }
    auto bytes = r.bytes(static_cast<size_t>(length));
    block.message.assign(bytes.begin(), bytes.end());
    demo.blocks.push_back(std::move(block));
    return true;
}

void append_u32(std::vector<uint8_t>& out, uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

}  // namespace

Result<Demo> parse_dem(std::span<const uint8_t> data, const std::string& name,
                       const DemParseOptions& options) {
    return capture_errors(name, [&]() -> Demo {
        ByteReader r(data, name);
        Demo demo;
        read_cd_track_line(r, demo);
        while (read_block(r, demo, options)) {
        }
        if (demo.blocks.empty()) demo.warnings.push_back("demo holds no message blocks");
        return demo;
    });
}

std::vector<uint8_t> write_dem(const Demo& demo) {
    std::vector<uint8_t> out(demo.cd_track_line.begin(), demo.cd_track_line.end());
    out.push_back('\n');
    for (const auto& block : demo.blocks) {
        append_u32(out, static_cast<uint32_t>(block.message.size()));
        for (float a : block.view_angles) {
            uint32_t bits;
            std::memcpy(&bits, &a, sizeof bits);
            append_u32(out, bits);
        }
        out.insert(out.end(), block.message.begin(), block.message.end());
    }
    return out;
}

}  // namespace nq
