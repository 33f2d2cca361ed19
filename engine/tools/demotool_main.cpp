// demotool: inspect Quake demos (.dem, protocols 15 / 666 / 999).
//   demotool info FILE.dem [--json] [--protocol N]     summary of the whole demo
//   demotool dump FILE.dem [--from N] [--count M] [--protocol N]   decoded messages per block
// --protocol sets the protocol assumed before the demo's first svc_serverinfo (default 15).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "common/file_io.h"
#include "common/json_writer.h"
#include "formats/demo_summary.h"

namespace {

using namespace nq;

constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

struct Options {
    std::string command;
    std::string file;
    bool json = false;
    size_t from = 0;
    size_t count = SIZE_MAX;
    protocol::ProtocolState initial;
};

constexpr const char* kUsage =
    "usage: demotool info FILE.dem [--json] [--protocol N]\n"
    "       demotool dump FILE.dem [--from N] [--count M] [--protocol N]\n"
    "  info: protocol, map, precaches, blocks, message histogram, duration\n"
    "  dump: the decoded messages of blocks [N, N + M)\n"
    "  --protocol: the protocol assumed before the first svc_serverinfo (default 15)\n"
    "  Options may come before or after the file.\n";

int usage() {
    std::fputs(kUsage, stderr);
    return kExitUsage;
}

bool parse_number(const char* text, size_t& out) {
    char* end = nullptr;
    unsigned long long v = std::strtoull(text, &end, 10);
    if (end == text || *end != '\0') return false;
    out = static_cast<size_t>(v);
    return true;
}

// Returns false on a malformed command line.
// Returns false on a malformed command line. The command comes first; options and the file
// in any order after it.
bool parse_options(int argc, char** argv, Options& o) {
    if (argc < 3) return false;
    o.command = argv[1];
    for (int i = 2; i < argc; ++i) {
        std::string_view arg = argv[i];
        bool has_value = i + 1 < argc;
        size_t n = 0;
        if (arg == "--json") {
            o.json = true;
        } else if (arg == "--from" && has_value && parse_number(argv[++i], n)) {
            o.from = n;
        } else if (arg == "--count" && has_value && parse_number(argv[++i], n)) {
            o.count = n;
        } else if (arg == "--protocol" && has_value && parse_number(argv[++i], n) &&
                   protocol::is_supported(static_cast<int32_t>(n))) {
            o.initial.protocol = static_cast<int>(n);
        } else if (!arg.starts_with("-") && o.file.empty()) {
            o.file = arg;
        } else {
            return false;
        }
    }
    return (o.command == "info" || o.command == "dump") && !o.file.empty();
}

std::string protocol_name(int p) {
    switch (p) {
        case protocol::kNetQuake:
            return "NetQuake";
        case protocol::kFitzQuake:
            return "FitzQuake";
        case protocol::kRmq:
            return "RMQ";
        default:
            return "unknown";
    }
}

std::vector<std::string> flag_names(uint32_t flags) {
    static const std::pair<uint32_t, const char*> kNames[] = {
        {protocol::PRFL_SHORTANGLE, "SHORTANGLE"}, {protocol::PRFL_FLOATANGLE, "FLOATANGLE"},
        {protocol::PRFL_24BITCOORD, "24BITCOORD"}, {protocol::PRFL_FLOATCOORD, "FLOATCOORD"},
        {protocol::PRFL_EDICTSCALE, "EDICTSCALE"}, {protocol::PRFL_ALPHASANITY, "ALPHASANITY"},
        {protocol::PRFL_INT32COORD, "INT32COORD"}, {protocol::PRFL_MOREFLAGS, "MOREFLAGS"}};
    std::vector<std::string> names;
    for (const auto& [bit, name] : kNames) {
        if (flags & bit) names.emplace_back(name);
    }
    return names;
}

std::string join(const std::vector<std::string>& parts, const char* sep) {
    std::string out;
    for (size_t i = 0; i < parts.size(); ++i) out += (i ? sep : "") + parts[i];
    return out;
}

// ---- info -----------------------------------------------------------------------------------

void print_list(const char* title, const std::vector<std::string>& names) {
    std::printf("%s (%zu):\n", title, names.size());
    for (size_t i = 0; i < names.size(); ++i) std::printf("  %4zu %s\n", i + 1, names[i].c_str());
}

void print_info_text(const DemoSummary& s) {
    std::printf("file:           %s\n", s.file.c_str());
    std::printf("cd track:       %d\n", s.cd_track);
    std::printf("protocol:       %d (%s)\n", s.protocol, protocol_name(s.protocol).c_str());
    if (s.protocol == protocol::kRmq) {
        std::printf("protocol flags: 0x%x (%s)\n", s.protocol_flags,
                    join(flag_names(s.protocol_flags), " | ").c_str());
    }
    std::printf("map:            %s\n", s.map.c_str());
    std::printf("level name:     %s\n", s.level_name.c_str());
    if (s.maps.size() > 1) std::printf("maps:           %s\n", join(s.maps, ", ").c_str());
    std::printf("blocks:         %zu (one recorded frame each)\n", s.blocks);
    std::printf("messages:       %zu (%zu bytes)\n", s.messages, s.message_bytes);
    std::printf("entity updates: %zu\n", s.entity_updates);
    std::printf("svc_time:       %zu messages, first %.3f s, last %.3f s\n", s.time_messages,
                s.first_time.value_or(0.0f), s.last_time.value_or(0.0f));
    std::printf("duration:       %.3f s (= last svc_time)\n", s.duration);
    std::printf("playback time:  %.3f s (sum over maps of last - first svc_time)\n",
                s.playback_time);
    print_list("models", s.models);
    print_list("sounds", s.sounds);
    std::printf("messages by kind:\n");
    for (const auto& k : s.histogram) {
        std::printf("  %-24s %8zu msgs %10zu bytes\n", k.name.c_str(), k.count, k.bytes);
    }
    std::printf("warnings (%zu):\n", s.warnings.size());
    for (const auto& w : s.warnings) std::printf("  %s\n", w.c_str());
}

void json_strings(JsonWriter& j, std::string_view key, const std::vector<std::string>& v) {
    j.key(key).begin_array();
    for (const auto& s : v) j.value(s);
    j.end_array();
}

void print_info_json(const DemoSummary& s) {
    JsonWriter j;
    j.begin_object();
    j.field("file", s.file).field("cd_track", s.cd_track).field("protocol", s.protocol);
    j.field("protocol_name", protocol_name(s.protocol));
    j.field("protocol_flags", s.protocol_flags);
    json_strings(j, "protocol_flag_names", flag_names(s.protocol_flags));
    j.field("map", s.map).field("level_name", s.level_name);
    json_strings(j, "maps", s.maps);
    j.field("blocks", static_cast<uint64_t>(s.blocks));
    j.field("messages", static_cast<uint64_t>(s.messages));
    j.field("message_bytes", static_cast<uint64_t>(s.message_bytes));
    j.field("entity_updates", static_cast<uint64_t>(s.entity_updates));
    j.field("time_messages", static_cast<uint64_t>(s.time_messages));
    j.key("first_time");
    s.first_time ? j.value(static_cast<double>(*s.first_time)) : j.null();
    j.key("last_time");
    s.last_time ? j.value(static_cast<double>(*s.last_time)) : j.null();
    j.field("duration", static_cast<double>(s.duration));
    j.field("duration_definition", "last svc_time value");
    j.field("playback_time", static_cast<double>(s.playback_time));
    json_strings(j, "models", s.models);
    json_strings(j, "sounds", s.sounds);
    j.key("histogram").begin_array();
    for (const auto& k : s.histogram) {
        j.begin_object().field("kind", k.kind).field("name", k.name);
        j.field("count", static_cast<uint64_t>(k.count));
        j.field("bytes", static_cast<uint64_t>(k.bytes)).end_object();
    }
    j.end_array();
    json_strings(j, "warnings", s.warnings);
    j.end_object();
    std::printf("%s\n", j.str().c_str());
}

// ---- dump -----------------------------------------------------------------------------------

std::string vec(const Vec3& v) {
    std::ostringstream o;
    o << '(' << v[0] << ' ' << v[1] << ' ' << v[2] << ')';
    return o.str();
}

std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '\n' ? std::string("\\n") : std::string(1, c);
    return out + "\"";
}

std::string hex(uint32_t v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", v);
    return buf;
}

std::string state_text(const EntityState& s) {
    std::ostringstream o;
    o << "model=" << s.model << " frame=" << s.frame << " colormap=" << s.colormap
      << " skin=" << s.skin << " origin=" << vec(s.origin) << " angles=" << vec(s.angles)
      << " alpha=" << s.alpha;
    return o.str();
}

std::string static_sound_text(const StaticSoundFields& s) {
    std::ostringstream o;
    o << "origin=" << vec(s.origin) << " sound=" << s.sound << " volume=" << s.volume
      << " attenuation=" << s.attenuation;
    return o.str();
}

// One-line description of a message's fields (the kind name is printed separately).
struct Describe {
    template <class Empty>
    requires std::is_empty_v<Empty> std::string operator()(const Empty&) const { return ""; }
    std::string operator()(const svc::UpdateStat& m) const {
        return "stat=" + std::to_string(m.stat) + " value=" + std::to_string(m.value);
    }
    std::string operator()(const svc::Version& m) const {
        return "protocol=" + std::to_string(m.protocol);
    }
    std::string operator()(const svc::SetView& m) const {
        return "entity=" + std::to_string(m.entity);
    }
    std::string operator()(const svc::Sound& m) const {
        std::ostringstream o;
        o << "mask=" << hex(m.field_mask) << " entity=" << m.entity << " channel=" << m.channel
          << " sound=" << m.sound << " volume=" << m.volume << " attenuation=" << m.attenuation
          << " origin=" << vec(m.origin);
        return o.str();
    }
    std::string operator()(const svc::Time& m) const {
        std::ostringstream o;
        o << "time=" << m.time;
        return o.str();
    }
    std::string operator()(const svc::Print& m) const { return quoted(m.text); }
    std::string operator()(const svc::StuffText& m) const { return quoted(m.text); }
    std::string operator()(const svc::CenterPrint& m) const { return quoted(m.text); }
    std::string operator()(const svc::Finale& m) const { return quoted(m.text); }
    std::string operator()(const svc::Cutscene& m) const { return quoted(m.text); }
    std::string operator()(const svc::Skybox& m) const { return quoted(m.name); }
    std::string operator()(const svc::SetAngle& m) const { return "angles=" + vec(m.angles); }
    std::string operator()(const svc::ServerInfo& m) const {
        return "protocol=" + std::to_string(m.protocol) + " flags=" + hex(m.protocol_flags) +
               " max_clients=" + std::to_string(m.max_clients) +
               " game_type=" + std::to_string(m.game_type) + " level=" + quoted(m.level_name) +
               " models=" + std::to_string(m.models.size()) +
               " sounds=" + std::to_string(m.sounds.size());
    }
    std::string operator()(const svc::LightStyle& m) const {
        return "style=" + std::to_string(m.style) + " " + quoted(m.pattern);
    }
    std::string operator()(const svc::UpdateName& m) const {
        return "client=" + std::to_string(m.client) + " " + quoted(m.name);
    }
    std::string operator()(const svc::UpdateFrags& m) const {
        return "client=" + std::to_string(m.client) + " frags=" + std::to_string(m.frags);
    }
    std::string operator()(const svc::ClientData& m) const {
        std::ostringstream o;
        o << "bits=" << hex(m.bits) << " viewheight=" << m.view_height
          << " items=" << hex(static_cast<uint32_t>(m.items)) << " health=" << m.health
          << " armor=" << m.armor << " weapon=" << m.weapon << " ammo=" << m.ammo
          << " shells/nails/rockets/cells=" << m.shells << '/' << m.nails << '/' << m.rockets << '/'
          << m.cells << " velocity=(" << m.velocity[0] << ' ' << m.velocity[1] << ' '
          << m.velocity[2] << ") onground=" << m.on_ground();
        return o.str();
    }
    std::string operator()(const svc::StopSound& m) const {
        return "entity=" + std::to_string(m.entity) + " channel=" + std::to_string(m.channel);
    }
    std::string operator()(const svc::UpdateColors& m) const {
        return "client=" + std::to_string(m.client) + " colors=" + std::to_string(m.colors);
    }
    std::string operator()(const svc::Particle& m) const {
        return "origin=" + vec(m.origin) + " direction=" + vec(m.direction) +
               " count=" + std::to_string(m.count) + " color=" + std::to_string(m.color);
    }
    std::string operator()(const svc::Damage& m) const {
        return "armor=" + std::to_string(m.armor) + " blood=" + std::to_string(m.blood) +
               " from=" + vec(m.from);
    }
    std::string operator()(const svc::SpawnStatic& m) const { return state_text(m.state); }
    std::string operator()(const svc::SpawnStatic2& m) const {
        return "flags=" + hex(m.flags) + " " + state_text(m.state);
    }
    std::string operator()(const svc::SpawnBaseline& m) const {
        return "entity=" + std::to_string(m.entity) + " " + state_text(m.state);
    }
    std::string operator()(const svc::SpawnBaseline2& m) const {
        return "entity=" + std::to_string(m.entity) + " flags=" + hex(m.flags) + " " +
               state_text(m.state);
    }
    std::string operator()(const svc::TempEntity& m) const {
        std::string out = std::string(protocol::temp_entity_name(m.type)) + " " + vec(m.origin);
        if (protocol::is_beam(m.type)) {
            out += " entity=" + std::to_string(m.entity) + " end=" + vec(m.end);
        }
        if (m.type == protocol::TE_EXPLOSION2) {
            out +=
                " colors=" + std::to_string(m.color_start) + "+" + std::to_string(m.color_length);
        }
        return out;
    }
    std::string operator()(const svc::SetPause& m) const {
        return "paused=" + std::to_string(m.paused);
    }
    std::string operator()(const svc::SignonNum& m) const {
        return "stage=" + std::to_string(m.stage);
    }
    std::string operator()(const svc::SpawnStaticSound& m) const {
        return static_sound_text(m.fields);
    }
    std::string operator()(const svc::SpawnStaticSound2& m) const {
        return static_sound_text(m.fields);
    }
    std::string operator()(const svc::CdTrack& m) const {
        return "track=" + std::to_string(m.track) + " loop=" + std::to_string(m.loop_track);
    }
    std::string operator()(const svc::Fog& m) const {
        std::ostringstream o;
        o << "density=" << m.density << " color=" << vec(m.color) << " time=" << m.fade_time;
        return o.str();
    }
    std::string operator()(const svc::EntityUpdate& m) const {
        std::ostringstream o;
        o << "entity=" << m.entity << " bits=" << hex(m.bits);
        if (m.has(protocol::U_MODEL) || m.has(protocol::U_MODEL2)) o << " model=" << m.model;
        if (m.has(protocol::U_FRAME) || m.has(protocol::U_FRAME2)) o << " frame=" << m.frame;
        if (m.has(protocol::U_ORIGIN1 | protocol::U_ORIGIN2 | protocol::U_ORIGIN3)) {
            o << " origin=" << vec(m.origin);
        }
        if (m.has(protocol::U_ANGLE1 | protocol::U_ANGLE2 | protocol::U_ANGLE3)) {
            o << " angles=" << vec(m.angles);
        }
        if (m.has(protocol::U_EFFECTS)) o << " effects=" << m.effects;
        if (m.has(protocol::U_ALPHA)) o << " alpha=" << m.alpha;
        return o.str();
    }
};

void dump_blocks(const DecodedDemo& d, const Options& o) {
    std::printf("cd track line: \"%s\", %zu blocks\n", d.demo.cd_track_line.c_str(),
                d.demo.blocks.size());
    size_t end = d.demo.blocks.size();
    if (o.count < end - std::min(o.from, end)) end = o.from + o.count;
    for (size_t b = std::min(o.from, end); b < end; ++b) {
        const DemoBlock& block = d.demo.blocks[b];
        std::printf("block %zu  offset %llu  %zu bytes  view angles %s\n", b,
                    static_cast<unsigned long long>(block.offset), block.message.size(),
                    vec(block.view_angles).c_str());
        for (const DecodedMessage& m : d.blocks[b].messages) {
            std::string name(message_kind_name(message_kind(m.message)));
            std::printf("  +%-5zu %-22s %s\n", m.offset, name.c_str(),
                        std::visit(Describe{}, m.message).c_str());
        }
        for (const auto& w : d.blocks[b].warnings) std::printf("  warning: %s\n", w.c_str());
    }
    for (const auto& w : d.demo.warnings) std::printf("warning: %s\n", w.c_str());
}

int run(const Options& o) {
    auto bytes = read_file(o.file);
    if (!bytes) {
        std::fprintf(stderr, "demotool: %s\n", bytes.error().to_string().c_str());
        return kExitError;
    }
    auto decoded = decode_demo(bytes.value(), o.file, o.initial);
    if (!decoded) {
        std::fprintf(stderr, "demotool: %s\n", decoded.error().to_string().c_str());
        return kExitError;
    }
    if (o.command == "dump") {
        dump_blocks(decoded.value(), o);
        return kExitOk;
    }
    DemoSummary summary = summarize_demo(decoded.value(), o.file);
    o.json ? print_info_json(summary) : print_info_text(summary);
    return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
    for (int i = 1; i < argc; ++i) {
        if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") {
            std::fputs(kUsage, stdout);
            return kExitOk;
        }
    }
    Options options;
    if (!parse_options(argc, argv, options)) return usage();
    return run(options);
}
