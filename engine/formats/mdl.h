// Quake alias models ("IDPO", version 6): an 84-byte header, skins (single or animated groups
// of skinwidth x skinheight palette indices), per-vertex texture coordinates, triangles, and
// frames (single poses or animated groups of poses) of byte-quantised vertices that decode as
// position = scale * v + scale_origin.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"

namespace nq {

class ByteReader;

using Vec3 = std::array<float, 3>;

inline constexpr int32_t kMdlVersion = 6;
inline constexpr size_t kMdlHeaderBytes = 84;
inline constexpr int kNumVertexNormals = 162;  // size of Quake's precomputed normal table

// Model flags (the header's `flags` field): trail and rotation effects.
enum MdlFlag : int32_t {
    kEfRocket = 1,
    kEfGrenade = 2,
    kEfGib = 4,
    kEfRotate = 8,
    kEfTracer = 16,
    kEfZomGib = 32,
    kEfTracer2 = 64,
    kEfTracer3 = 128,
};

struct MdlHeader {
    int32_t version = 0;
    Vec3 scale{};
    Vec3 scale_origin{};
    float bounding_radius = 0;
    Vec3 eye_position{};
    int32_t num_skins = 0;
    int32_t skin_width = 0;
    int32_t skin_height = 0;
    int32_t num_verts = 0;
    int32_t num_tris = 0;
    int32_t num_frames = 0;
    int32_t sync_type = 0;  // 0 = animations in sync, 1 = random start
    int32_t flags = 0;
    float size = 0;  // average triangle size, informational
};

// A skin: one image, or an animated group of images shown for the given intervals.
struct MdlSkin {
    bool is_group = false;
    std::vector<float> intervals;  // group only: cumulative end times, positive and increasing
    std::vector<std::vector<uint8_t>> images;  // skin_width * skin_height indices each
};

struct MdlTexCoord {
    int32_t on_seam = 0;  // non-zero: back-facing triangles use s + skin_width / 2
    int32_t s = 0;
    int32_t t = 0;
};

struct MdlTriangle {
    int32_t faces_front = 0;
    std::array<int32_t, 3> vertices{};  // each < num_verts (validated)
};

// A quantised vertex: position bytes plus an index into the 162-entry normal table.
struct TriVertex {
    std::array<uint8_t, 3> v{};
    uint8_t light_normal_index = 0;  // < kNumVertexNormals (clamped, with a warning)
};

// One pose: bounding box and num_verts vertices, as stored.
struct MdlPose {
    TriVertex bbox_min;
    TriVertex bbox_max;
    std::string name;
    std::vector<TriVertex> vertices;
};

// A frame: one pose, or an animated group of poses with their intervals.
struct MdlFrame {
    bool is_group = false;
    TriVertex group_bbox_min;      // group only
    TriVertex group_bbox_max;      // group only
    std::vector<float> intervals;  // group only, one per pose
    std::vector<MdlPose> poses;    // exactly one for a single frame
};

struct Mdl {
    MdlHeader header;
    std::vector<MdlSkin> skins;
    std::vector<MdlTexCoord> tex_coords;  // num_verts entries
    std::vector<MdlTriangle> triangles;
    std::vector<MdlFrame> frames;
    uint64_t data_end = 0;        // offset just past the last frame
    uint64_t trailing_bytes = 0;  // e.g. a "QMEX" editor block some tools append
    std::vector<std::string> warnings;
};

Result<Mdl> parse_mdl(std::span<const uint8_t> data, const std::string& name);

// Decoded model-space position of a vertex: scale * v + scale_origin.
Vec3 decode_vertex(const MdlHeader& header, const TriVertex& vertex);
std::vector<Vec3> decoded_positions(const MdlHeader& header, const MdlPose& pose);

struct Bounds {
    Vec3 min{};
    Vec3 max{};
    bool contains(const Vec3& p, float epsilon = 0) const;
};
// Union of the decoded bounding boxes stored with every pose (and group) of every frame.
Bounds decoded_frame_bounds(const Mdl& mdl);

// Names of the set flag bits ("rocket", "rotate", ...); unknown bits as "0x100" etc.
std::vector<std::string> mdl_flag_names(int32_t flags);
const char* sync_type_name(int32_t sync_type);  // "sync", "rand" or "unknown"

// Animation intervals must be positive and strictly increasing (they are cumulative times).
// Replaces each offending value (including NaN/inf) by the previous one plus 0.1 s and
// returns how many were replaced. Shared by models and sprites.
size_t repair_intervals(std::vector<float>& intervals);

// Parsing helpers shared with the sprite parser (they throw FormatError like ByteReader).
// Reads `count` cumulative intervals, repairing bad ones with a warning naming `owner`.
std::vector<float> read_animation_intervals(ByteReader& in, int32_t count, const std::string& owner,
                                            std::vector<std::string>& warnings);
// A float that only informs (radius, eye, size): NaN/inf becomes 0 with a warning.
float read_informational_float(ByteReader& in, const char* what,
                               std::vector<std::string>& warnings);

}  // namespace nq
