// parse_bsp: the header, the lump directory, and the order in which lumps are read and checked.
#include "formats/bsp.h"

#include <cctype>

#include "formats/bsp_internal.h"

namespace nq {

using namespace bsp_detail;

const char* bsp_format_name(BspFormat format) {
    switch (format) {
        case BspFormat::bsp29:
            return "BSP29";
        case BspFormat::bsp2:
            return "BSP2";
        case BspFormat::bsp2psb:
            return "2PSB";
    }
    return "unknown";
}

namespace bsp_detail {

const char* lump_name(int lump) {
    static const char* const kNames[kLumpCount] = {
        "entities", "planes",       "textures", "vertexes",  "visibility",
        "nodes",    "texinfo",      "faces",    "lighting",  "clipnodes",
        "leafs",    "marksurfaces", "edges",    "surfedges", "models"};
    return lump >= 0 && lump < kLumpCount ? kNames[lump] : "?";
}

size_t record_size(int lump, BspFormat format) {
    const bool bsp29 = format == BspFormat::bsp29;
    const bool floats = format == BspFormat::bsp2;  // BSP2 has float bounds, 2PSB shorts
    switch (lump) {
        case kPlanes:
            return 20;
        case kVertexes:
            return 12;
        case kNodes:
            return bsp29 ? 24 : (floats ? 44 : 32);
        case kTexinfo:
            return 40;
        case kFaces:
            return bsp29 ? 20 : 28;
        case kClipnodes:
            return bsp29 ? 8 : 12;
        case kLeafs:
            return bsp29 ? 28 : (floats ? 44 : 32);
        case kMarksurfaces:
            return bsp29 ? 2 : 4;
        case kEdges:
            return bsp29 ? 4 : 8;
        case kSurfedges:
            return 4;
        case kModels:
            return 64;
        default:
            return 1;  // entities, textures, visibility, lighting: raw bytes
    }
}

ByteReader ReadContext::lump_reader(int lump) const {
    return file.sub(lumps[lump].offset, lumps[lump].length, std::string(lump_name(lump)) + " lump");
}

uint64_t ReadContext::record_offset(int lump, size_t index) const {
    return file.absolute(lumps[lump].offset) + uint64_t{index} * record_size(lump, format);
}

void ReadContext::fail_record(int lump, size_t index, std::string message) const {
    throw FormatError(Error{file.file(), record_offset(lump, index), std::move(message)});
}

std::string FieldName::str() const {
    return std::string(record) + " " + std::to_string(index) + " " + field;
}

void check_index(const ByteReader& r, size_t pos, int64_t value, size_t count,
                 const FieldName& what) {
    if (value < 0 || static_cast<uint64_t>(value) >= count) {
        r.fail_at(pos, what.str() + " " + std::to_string(value) + " out of range (" +
                           std::to_string(count) + " available)");
    }
}

void check_range(const ByteReader& r, size_t pos, int64_t first, int64_t num, size_t count,
                 const FieldName& what) {
    if (first < 0 || num < 0 || static_cast<uint64_t>(first) > count ||
        static_cast<uint64_t>(num) > count - static_cast<uint64_t>(first)) {
        r.fail_at(pos, what.str() + " [" + std::to_string(first) + ", +" + std::to_string(num) +
                           ") out of range (" + std::to_string(count) + " available)");
    }
}

}  // namespace bsp_detail

namespace {

constexpr uint32_t fourcc(const char (&s)[5]) {
    return static_cast<uint32_t>(static_cast<uint8_t>(s[0])) |
           static_cast<uint32_t>(static_cast<uint8_t>(s[1])) << 8 |
           static_cast<uint32_t>(static_cast<uint8_t>(s[2])) << 16 |
           static_cast<uint32_t>(static_cast<uint8_t>(s[3])) << 24;
}

std::string describe_magic(uint32_t magic) {
    std::string text = std::to_string(static_cast<int32_t>(magic));
    std::string chars;
    for (int i = 0; i < 4; ++i) {
        char c = static_cast<char>((magic >> (8 * i)) & 0xff);
        if (!std::isprint(static_cast<unsigned char>(c))) return text;
        chars += c;
    }
    return text + " (\"" + chars + "\")";
}

BspFormat read_format(ByteReader& file) {
    if (file.size() < kHeaderBytes) {
        file.fail_at(0, "truncated header: " + std::to_string(file.size()) + " bytes, a BSP " +
                            "header needs " + std::to_string(kHeaderBytes));
    }
    uint32_t magic = file.u32();
    if (magic == 29) return BspFormat::bsp29;
    if (magic == fourcc("BSP2")) return BspFormat::bsp2;
    if (magic == fourcc("2PSB")) return BspFormat::bsp2psb;
    file.fail_at(0, "unsupported BSP version " + describe_magic(magic) +
                        " (expected 29, \"BSP2\" or \"2PSB\")");
}

std::array<LumpSpan, kLumpCount> read_directory(ByteReader& file, BspFormat format) {
    std::array<LumpSpan, kLumpCount> lumps;
    for (int i = 0; i < kLumpCount; ++i) {
        const size_t at = file.tell();
        const int32_t offset = file.i32();
        const int32_t length = file.i32();
        const std::string what =
            std::string("lump ") + std::to_string(i) + " (" + lump_name(i) + ")";
        if (offset < 0 || length < 0) {
            file.fail_at(at, what + " has negative offset " + std::to_string(offset) +
                                 " or length " + std::to_string(length));
        }
        const auto off = static_cast<size_t>(offset);
        const auto len = static_cast<size_t>(length);
        if (off > file.size() || len > file.size() - off) {
            file.fail_at(at, what + " [" + std::to_string(off) + ", +" + std::to_string(len) +
                                 ") lies beyond the end of the file (" +
                                 std::to_string(file.size()) + " bytes)");
        }
        const size_t record = record_size(i, format);
        if (len % record != 0) {
            file.fail_at(at + 4, what + " size " + std::to_string(len) + " is not a multiple of " +
                                     "its " + std::to_string(record) + "-byte record");
        }
        lumps[i] = {off, len};
    }
    return lumps;
}

void read_all_lumps(const ReadContext& ctx) {
    // Every reader checks indices against the counts in the directory, so order only matters
    // where a reader needs another lump's *contents*: texinfo needs the texture count.
    read_entities(ctx);
    read_planes(ctx);
    read_textures(ctx);
    read_vertices(ctx);
    read_texinfo(ctx);
    read_faces(ctx);
    read_edges(ctx);
    read_surfedges(ctx);
    read_marksurfaces(ctx);
    read_leafs(ctx);
    read_nodes(ctx);
    read_clipnodes(ctx);
    read_models(ctx);
    auto vis = ctx.lump_reader(kVisibility).bytes(ctx.lumps[kVisibility].length);
    ctx.out.visibility.assign(vis.begin(), vis.end());
    auto light = ctx.lump_reader(kLighting).bytes(ctx.lumps[kLighting].length);
    ctx.out.lighting.assign(light.begin(), light.end());
}

}  // namespace

Result<Bsp> parse_bsp(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&]() -> Bsp {
        ByteReader file(data, name);
        Bsp bsp;
        bsp.name = name;
        bsp.format = read_format(file);
        ReadContext ctx{file, bsp.format, read_directory(file, bsp.format), bsp};
        read_all_lumps(ctx);
        compute_face_lightmaps(ctx);
        build_hulls(ctx);
        validate_vis_rows(ctx);
        return bsp;
    });
}

}  // namespace nq
