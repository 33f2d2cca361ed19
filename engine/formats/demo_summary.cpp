#include "formats/demo_summary.h"

#include <array>
#include <optional>
#include <variant>

namespace nq {
namespace {

// Running state of the pass that the summary itself does not keep.
struct Scan {
    bool map_changed = false;            // a later serverinfo restarts the server clock
    // The first and last svc_time since the last serverinfo (a plain pair with a flag: GCC 12
    // cannot see that two optionals are always set together, and warns).
    bool segment_open = false;
    float segment_first = 0.0f;
    float segment_last = 0.0f;
};

// Adds the svc_time span of the map segment that just ended to the playback time.
void close_segment(DemoSummary& s, Scan& scan) {
    if (scan.segment_open) s.playback_time += scan.segment_last - scan.segment_first;
    scan.segment_open = false;
}

void note_server_info(const svc::ServerInfo& si, DemoSummary& s, Scan& scan) {
    scan.map_changed = s.has_server_info;
    close_segment(s, scan);
    s.maps.push_back(si.models.empty() ? std::string() : si.models.front());
    if (s.has_server_info) return;  // later map changes only extend `maps`
    s.has_server_info = true;
    s.protocol = si.protocol;
    s.protocol_flags = si.protocol_flags;
    s.map = s.maps.back();
    s.level_name = si.level_name;
    s.models = si.models;
    s.sounds = si.sounds;
}

void note_time(float t, DemoSummary& s, Scan& scan) {
    if (!s.first_time) s.first_time = t;
    if (s.last_time && t < *s.last_time && !scan.map_changed) {
        s.warnings.push_back("svc_time goes backwards from " + std::to_string(*s.last_time) +
                             " to " + std::to_string(t));
    }
    s.last_time = t;
    scan.map_changed = false;
    if (!scan.segment_open) scan.segment_first = t;
    scan.segment_open = true;
    scan.segment_last = t;
    ++s.time_messages;
}

// Indexed by kind: 0..127 svc numbers, kEntityUpdateKind for fast updates.
using KindTable = std::array<MessageKindStats, kEntityUpdateKind + 1>;

void fill_histogram(const KindTable& table, DemoSummary& s) {
    for (size_t kind = 0; kind < table.size(); ++kind) {
        if (table[kind].count == 0) continue;
        MessageKindStats stats = table[kind];
        stats.kind = static_cast<int>(kind);
        stats.name = std::string(message_kind_name(stats.kind));
        s.histogram.push_back(std::move(stats));
    }
}

}  // namespace

Result<DecodedDemo> decode_demo(std::span<const uint8_t> data, const std::string& name,
                                protocol::ProtocolState initial) {
    auto demo = parse_dem(data, name);
    if (!demo) return demo.error();
    DecodedDemo out;
    out.demo = std::move(demo.value());
    out.blocks.reserve(out.demo.blocks.size());
    protocol::ProtocolState state = initial;
    for (size_t i = 0; i < out.demo.blocks.size(); ++i) {
        const DemoBlock& block = out.demo.blocks[i];
        auto decoded =
            decode_server_message(block.message, {name, i, block.message_offset()}, state);
        if (!decoded) return decoded.error();
        out.blocks.push_back(std::move(decoded.value()));
    }
    out.final_state = state;
    return out;
}

DemoSummary summarize_demo(const DecodedDemo& decoded, const std::string& name) {
    DemoSummary s;
    s.file = name;
    s.cd_track_line = decoded.demo.cd_track_line;
    s.cd_track = decoded.demo.cd_track;
    s.blocks = decoded.demo.blocks.size();
    s.warnings = decoded.demo.warnings;
    KindTable table{};
    Scan scan;
    for (size_t b = 0; b < decoded.blocks.size(); ++b) {
        for (const auto& w : decoded.blocks[b].warnings) {
            s.warnings.push_back("block " + std::to_string(b) + ": " + w);
        }
        for (const DecodedMessage& m : decoded.blocks[b].messages) {
            int kind = message_kind(m.message);
            ++table[kind].count;
            table[kind].bytes += m.size;
            ++s.messages;
            s.message_bytes += m.size;
            if (const auto* si = std::get_if<svc::ServerInfo>(&m.message))
                note_server_info(*si, s, scan);
            if (const auto* t = std::get_if<svc::Time>(&m.message)) note_time(t->time, s, scan);
        }
    }
    s.entity_updates = table[kEntityUpdateKind].count;
    close_segment(s, scan);
    s.duration = s.last_time.value_or(0.0f);
    if (!s.has_server_info) s.warnings.push_back("demo has no svc_serverinfo");
    fill_histogram(table, s);
    return s;
}

Result<DemoSummary> summarize_demo_file(std::span<const uint8_t> data, const std::string& name,
                                        protocol::ProtocolState initial) {
    auto decoded = decode_demo(data, name, initial);
    if (!decoded) return decoded.error();
    return summarize_demo(decoded.value(), name);
}

}  // namespace nq
