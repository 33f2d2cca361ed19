// Quake BSP maps: BSP29 (version 29) and the extended formats BSP2 ("BSP2") and 2PSB ("2PSB").
// parse_bsp() reads every lump into plain C++ data, validates every count, offset and index
// against the file, and derives what engines compute at load: lightmap extents per face and the
// three collision hulls. Queries on a parsed map (PVS rows, point contents, traces) live here too.
//
// Tree safety: the node graph (hull 0) and the clipnode graph (hulls 1 and 2) are checked at load
// to be acyclic and at most kMaxBspTreeDepth levels deep from every node. Compilers write children
// after their parents, but the check does not rely on that (a tool may share subtrees); it only
// guarantees that every traversal ends, so the queries below can walk or recurse without limits.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

using BspVec3 = std::array<float, 3>;

enum class BspFormat {
    bsp29,   // version 29: 16-bit node/leaf/edge/marksurface/clipnode indices, short bounds
    bsp2,    // "BSP2": 32-bit indices, float bounds in nodes and leafs
    bsp2psb  // "2PSB": 32-bit indices, short bounds in nodes and leafs
};
const char* bsp_format_name(BspFormat format);

// Leaf and clip-hull contents (always negative, so a child value < 0 is never a node index).
namespace bsp_contents {
inline constexpr int32_t empty = -1;
inline constexpr int32_t solid = -2;
inline constexpr int32_t water = -3;
inline constexpr int32_t slime = -4;
inline constexpr int32_t lava = -5;
inline constexpr int32_t sky = -6;
inline constexpr int32_t lowest_valid = -15;  // -7..-14 are origin, clip and current brushes
}  // namespace bsp_contents

inline constexpr int kBspMipLevels = 4;
inline constexpr int kBspMaxLightStyles = 4;
inline constexpr uint8_t kBspNoLightStyle = 255;
inline constexpr uint32_t kBspTexinfoSpecial = 1;  // sky/liquid: no lightmap, warped or scrolled
inline constexpr int kBspMaxTreeDepth = 1024;      // deeper node/clipnode chains are rejected

struct BspPlane {
    BspVec3 normal{};
    float dist = 0;
    int32_t type = 0;  // 0..2 axial X/Y/Z, 3..5 mostly X/Y/Z (informational only)
};

struct BspMipLevel {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<uint8_t> pixels;  // width * height palette indices, row by row
};

struct BspTexture {
    std::string name;
    uint32_t width = 0;  // level 0 size; level i is (width >> i) x (height >> i)
    uint32_t height = 0;
    std::array<BspMipLevel, kBspMipLevels> mips;
    // True when the file had no usable pixels for this slot (offset -1, data kept in a WAD,
    // zero size): the mips then hold a 16x16 checkerboard and a warning was recorded.
    bool placeholder = false;
};

struct BspTexinfo {
    // s = dot(xyz, vecs[0].xyz) + vecs[0][3]; t likewise with vecs[1] (texels, unscaled).
    std::array<std::array<float, 4>, 2> vecs{};
    uint32_t miptex = 0;  // index into Bsp::textures
    uint32_t flags = 0;   // kBspTexinfoSpecial
};

struct BspFace {
    uint32_t plane = 0;
    bool back_side = false;  // the face looks along -plane.normal
    uint32_t first_surfedge = 0;
    uint32_t num_surfedges = 0;  // = number of vertices, >= 3
    uint32_t texinfo = 0;
    std::array<uint8_t, kBspMaxLightStyles> styles{};  // kBspNoLightStyle ends the list
    int32_t light_offset = -1;                         // byte offset in Bsp::lighting, -1 = none

    // Derived at load from the texinfo and the face's vertices (texels of the texture):
    std::array<int32_t, 2> texture_mins{};  // multiples of 16
    std::array<int32_t, 2> extents{};       // multiples of 16
    uint32_t lightmap_width = 0;            // extents[0] / 16 + 1 (0 when unlit)
    uint32_t lightmap_height = 0;
    uint32_t num_styles = 0;  // styles before the first 255

    bool has_lightmap() const { return light_offset >= 0 && num_styles > 0; }
    // Bytes of one style's lightmap (one byte per sample).
    uint32_t lightmap_samples() const { return lightmap_width * lightmap_height; }
};

struct BspEdge {
    std::array<uint32_t, 2> v{};  // vertex indices
};

// Children: >= 0 is a node index, < 0 is leaf number -(child + 1).
struct BspNode {
    uint32_t plane = 0;
    std::array<int32_t, 2> children{};  // [0] in front of the plane (dist >= 0), [1] behind
    BspVec3 mins{};
    BspVec3 maxs{};
    uint32_t first_face = 0;
    uint32_t num_faces = 0;
};

struct BspLeaf {
    int32_t contents = bsp_contents::solid;
    int32_t vis_offset = -1;  // into Bsp::visibility; -1 = no PVS (everything visible)
    BspVec3 mins{};
    BspVec3 maxs{};
    uint32_t first_marksurface = 0;
    uint32_t num_marksurfaces = 0;
    std::array<uint8_t, 4> ambient_levels{};  // water, sky, slime, lava sound volumes
};

// Children: >= 0 is a clipnode index, < 0 is a contents value (bsp_contents).
struct BspClipNode {
    uint32_t plane = 0;
    std::array<int32_t, 2> children{};
};

struct BspModel {
    BspVec3 mins{};
    BspVec3 maxs{};
    BspVec3 origin{};
    // [0] node index (hull 0); [1], [2] clipnode indices (hulls 1, 2); [3] unused by Quake,
    // kept as read and not validated.
    std::array<int32_t, 4> headnodes{};
    uint32_t visleafs = 0;  // leafs of this model, not counting leaf 0
    uint32_t first_face = 0;
    uint32_t num_faces = 0;
};

// A collision hull: a clipnode tree of planes already pushed out by the box it collides.
struct BspHull {
    std::vector<BspClipNode> clipnodes;  // start at BspModel::headnodes[hull]
    BspVec3 clip_mins{};                 // the box a point in this hull stands for
    BspVec3 clip_maxs{};
};

struct Bsp {
    std::string name;
    BspFormat format = BspFormat::bsp29;

    std::string entities;          // entity lump text, up to its NUL (see entities.h)
    uint64_t entities_offset = 0;  // file offset of that text, for error messages

    std::vector<BspPlane> planes;
    std::vector<BspTexture> textures;
    std::vector<BspVec3> vertices;
    std::vector<uint8_t> visibility;  // compressed PVS rows, see decompress_vis
    std::vector<BspNode> nodes;
    std::vector<BspTexinfo> texinfo;
    std::vector<BspFace> faces;
    std::vector<uint8_t> lighting;       // one byte per lightmap sample (see parse_lit for colour)
    std::vector<BspLeaf> leafs;          // leaf 0 is the shared solid leaf
    std::vector<uint32_t> marksurfaces;  // face indices
    std::vector<BspEdge> edges;
    std::vector<int32_t> surfedges;  // edge index; negative = that edge walked backwards
    std::vector<BspModel> models;    // model 0 is the world, then brush entities ("*1", ...)

    // hulls[0] is derived from nodes and leaf contents (point-sized); hulls[1] (player,
    // -16 -16 -24 .. 16 16 32) and hulls[2] (large monsters, -32 -32 -24 .. 32 32 64) both hold
    // the clipnodes lump.
    std::array<BspHull, 3> hulls;

    std::vector<std::string> warnings;
};

Result<Bsp> parse_bsp(std::span<const uint8_t> data, const std::string& name);

// ---- PVS (bsp_vis.cpp) ----

// Bytes in one decompressed PVS row: (models[0].visleafs + 7) / 8, one bit per *world* leaf.
// Brush-entity leafs follow the world's in the leafs lump and have no bits, so this is less than
// (leafs.size() - 1 + 7) / 8 in maps with brush entities (start.bsp: 69 leafs, 20 world leafs,
// 3-byte rows); rows that long would run past what the vis tool wrote.
size_t pvs_row_bytes(const Bsp& bsp);
// The set of leafs visible from `leaf`; bit (i - 1) stands for leaf i. Leaf 0 (solid) and
// leafs out of range see nothing; a leaf without PVS data (vis_offset -1) sees every leaf.
// Rows were validated at load; decoding still stops at the end of the data.
std::vector<uint8_t> decompress_vis(const Bsp& bsp, uint32_t leaf);
// Whether `row` (from decompress_vis) marks `leaf` (>= 1) visible.
bool pvs_contains(std::span<const uint8_t> row, uint32_t leaf);

// ---- Collision queries (bsp_collision.cpp); points are in the model's own space ----

// Contents of `point` in hull 0..2 of `model`; bsp_contents::solid for a bad hull or model.
int32_t point_contents(const Bsp& bsp, int hull, const BspVec3& point, size_t model = 0);
// The leaf (index into Bsp::leafs) holding `point` in `model`'s node tree.
uint32_t leaf_at(const Bsp& bsp, const BspVec3& point, size_t model = 0);

struct BspTrace {
    float fraction = 1;      // part of start..end travelled before hitting solid
    BspVec3 end{};           // where the trace stopped
    BspVec3 plane_normal{};  // of the surface hit, facing the start point
    float plane_dist = 0;
    bool start_solid = false;  // started inside solid
    bool all_solid = false;    // never left solid
    bool hit() const { return fraction < 1; }
};
// Sweeps a point (hull 0) or a box (hulls 1, 2: the box of BspHull::clip_mins/maxs around the
// point) from start to end and stops at the first solid.
BspTrace trace_hull(const Bsp& bsp, int hull, const BspVec3& start, const BspVec3& end,
                    size_t model = 0);
// Trace straight down up to max_distance: where the ground is and its plane (for shadows).
BspTrace trace_down(const Bsp& bsp, const BspVec3& from, float max_distance, int hull = 0);

// ---- Coloured lighting (.lit, bsp_lit.cpp) ----

struct BspLit {
    std::vector<uint8_t> rgb;  // 3 bytes per lightmap sample, parallel to Bsp::lighting;
                               // empty when the file does not match the map
    std::vector<std::string> warnings;
};
// A .lit file: "QLIT", int32 version 1, then 3 bytes per byte of the map's lighting lump.
// Bad magic or version is an error; a sample count other than expected_samples is a warning and
// the colour data is ignored (rgb left empty).
Result<BspLit> parse_lit(std::span<const uint8_t> data, const std::string& name,
                         size_t expected_samples);

}  // namespace nq
