// Shared between the bsp*.cpp files only: the lump directory and the reading context that the
// per-lump readers and the load-time validators work on. Not part of the public API.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "common/byte_reader.h"
#include "formats/bsp.h"

namespace nq::bsp_detail {

enum Lump : int {
    kEntities,
    kPlanes,
    kTextures,
    kVertexes,
    kVisibility,
    kNodes,
    kTexinfo,
    kFaces,
    kLighting,
    kClipnodes,
    kLeafs,
    kMarksurfaces,
    kEdges,
    kSurfedges,
    kModels,
    kLumpCount
};

inline constexpr size_t kHeaderBytes = 4 + kLumpCount * 8;

const char* lump_name(int lump);
// Bytes per record of `lump` in `format`; 1 for the lumps read as raw bytes.
size_t record_size(int lump, BspFormat format);

struct LumpSpan {
    size_t offset = 0;
    size_t length = 0;
};

// What the lump readers share: the whole file, the directory, the record counts of every lump
// (known from the header before any lump is read, so indices are checked as they are read).
struct ReadContext {
    const ByteReader& file;
    BspFormat format;
    std::array<LumpSpan, kLumpCount> lumps{};
    Bsp& out;

    ByteReader lump_reader(int lump) const;
    size_t count(int lump) const { return lumps[lump].length / record_size(lump, format); }
    // Absolute file offset of record `index` of `lump`, for errors found after reading.
    uint64_t record_offset(int lump, size_t index) const;
    [[noreturn]] void fail_record(int lump, size_t index, std::string message) const;
    bool wide() const { return format != BspFormat::bsp29; }
};

// Names a field of a record in error messages ("face 3 plane"); the text is only built when a
// check fails, so checking millions of fields costs no string work.
struct FieldName {
    const char* record;  // "face"
    size_t index;        // 3
    const char* field;   // "plane"
    std::string str() const;
};

// Fails at `pos` of `r` unless 0 <= value < count.
void check_index(const ByteReader& r, size_t pos, int64_t value, size_t count,
                 const FieldName& what);
// Fails unless [first, first + num) lies within [0, count).
void check_range(const ByteReader& r, size_t pos, int64_t first, int64_t num, size_t count,
                 const FieldName& what);

// Lump readers (bsp_lumps.cpp, bsp_textures.cpp), in dependency-free order: each only checks
// indices against counts, never against other lumps' contents.
void read_entities(const ReadContext& ctx);
void read_planes(const ReadContext& ctx);
void read_textures(const ReadContext& ctx);
void read_vertices(const ReadContext& ctx);
void read_texinfo(const ReadContext& ctx);
void read_faces(const ReadContext& ctx);
void read_edges(const ReadContext& ctx);
void read_surfedges(const ReadContext& ctx);
void read_marksurfaces(const ReadContext& ctx);
void read_leafs(const ReadContext& ctx);
void read_nodes(const ReadContext& ctx);
void read_clipnodes(const ReadContext& ctx);
void read_models(const ReadContext& ctx);

// Load-time derivations and checks that need several lumps' contents.
void compute_face_lightmaps(const ReadContext& ctx);  // bsp_lightmap.cpp
void build_hulls(const ReadContext& ctx);             // bsp_tree.cpp
void validate_vis_rows(const ReadContext& ctx);       // bsp_vis.cpp

}  // namespace nq::bsp_detail
