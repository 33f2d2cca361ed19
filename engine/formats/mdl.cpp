#include "formats/mdl.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/byte_reader.h"

namespace nq {

namespace {

// Header field offsets, for errors that point at the count that lies.
constexpr size_t kNumSkinsOffset = 48;
constexpr size_t kSkinWidthOffset = 52;
constexpr size_t kSkinHeightOffset = 56;
constexpr size_t kNumVertsOffset = 60;
constexpr size_t kNumTrisOffset = 64;
constexpr size_t kNumFramesOffset = 68;

constexpr size_t kTexCoordBytes = 12;
constexpr size_t kTriangleBytes = 16;
constexpr size_t kTriVertexBytes = 4;
constexpr size_t kFrameNameBytes = 16;
constexpr size_t kPoseHeaderBytes = 2 * kTriVertexBytes + kFrameNameBytes;

// The original engine's fixed-size tables; larger models only load in modern engines.
constexpr int32_t kClassicMaxVerts = 1024;
constexpr int32_t kClassicMaxTris = 2048;
constexpr int32_t kClassicMaxFrames = 256;
constexpr int32_t kClassicMaxSkins = 32;

constexpr float kRepairedIntervalStep = 0.1f;

// Counters for problems that can repeat per element: reported once, with a count.
struct Tally {
    size_t tex_coords_outside_skin = 0;
    int64_t first_tex_coord_outside = -1;
    size_t normals_clamped = 0;
};

Vec3 read_vec3_finite(ByteReader& in) {
    Vec3 v;
    for (float& c : v) c = in.f32_finite();
    return v;
}

MdlHeader read_header(ByteReader& in, std::vector<std::string>& warnings) {
    if (in.size() < kMdlHeaderBytes) in.fail("file too small for an MDL header (84 bytes)");
    std::string ident(reinterpret_cast<const char*>(in.bytes(4).data()), 4);
    if (ident != "IDPO") in.fail_at(0, "not an alias model (identifier is not \"IDPO\")");
    MdlHeader h;
    h.version = in.i32();
    if (h.version != kMdlVersion) {
        in.fail_at(4, "unsupported MDL version " + std::to_string(h.version) + " (expected 6)");
    }
    h.scale = read_vec3_finite(in);
    h.scale_origin = read_vec3_finite(in);
    h.bounding_radius = read_informational_float(in, "bounding radius", warnings);
    for (float& c : h.eye_position) c = read_informational_float(in, "eye position", warnings);
    h.num_skins = in.i32();
    h.skin_width = in.i32();
    h.skin_height = in.i32();
    h.num_verts = in.i32();
    h.num_tris = in.i32();
    h.num_frames = in.i32();
    h.sync_type = in.i32();
    h.flags = in.i32();
    h.size = read_informational_float(in, "size", warnings);
    return h;
}

// A count must be positive and small enough that `min_record_bytes` per element still fits
// in the bytes after the header.
void check_count(const ByteReader& in, size_t field_offset, int32_t count,
                 uint64_t min_record_bytes, const char* what) {
    if (count <= 0) {
        in.fail_at(field_offset,
                   std::string(what) + " must be positive, header says " + std::to_string(count));
    }
    const uint64_t available = in.size() - kMdlHeaderBytes;
    if (uint64_t(count) > available / min_record_bytes) {
        in.fail_at(field_offset, std::string(what) + " " + std::to_string(count) +
                                     " cannot fit in the " + std::to_string(available) +
                                     " bytes after the header");
    }
}

void warn_over_classic_limit(int32_t count, int32_t limit, const char* what,
                             std::vector<std::string>& warnings) {
    if (count > limit) {
        warnings.push_back(std::to_string(count) + " " + what + " exceed the original engine's " +
                           "limit of " + std::to_string(limit));
    }
}

void validate_header(const ByteReader& in, const MdlHeader& h, std::vector<std::string>& warn) {
    if (h.num_skins < 0) {
        in.fail_at(kNumSkinsOffset, "negative skin count " + std::to_string(h.num_skins));
    }
    if (h.skin_width <= 0) {
        in.fail_at(kSkinWidthOffset,
                   "skin width must be positive, header says " + std::to_string(h.skin_width));
    }
    if (h.skin_height <= 0) {
        in.fail_at(kSkinHeightOffset,
                   "skin height must be positive, header says " + std::to_string(h.skin_height));
    }
    check_count(in, kNumVertsOffset, h.num_verts, kTexCoordBytes, "vertex count");
    check_count(in, kNumTrisOffset, h.num_tris, kTriangleBytes, "triangle count");
    check_count(in, kNumFramesOffset, h.num_frames,
                4 + kPoseHeaderBytes + kTriVertexBytes * uint64_t(h.num_verts), "frame count");

    if (h.num_skins == 0) warn.push_back("model has no skins (the original engine refuses it)");
    if (h.skin_width % 4 != 0) {
        warn.push_back("skin width " + std::to_string(h.skin_width) +
                       " is not a multiple of 4 (the original engine refuses it)");
    }
    if (h.sync_type != 0 && h.sync_type != 1) {
        warn.push_back("unknown sync type " + std::to_string(h.sync_type));
    }
    warn_over_classic_limit(h.num_skins, kClassicMaxSkins, "skins", warn);
    warn_over_classic_limit(h.num_verts, kClassicMaxVerts, "vertices", warn);
    warn_over_classic_limit(h.num_tris, kClassicMaxTris, "triangles", warn);
    warn_over_classic_limit(h.num_frames, kClassicMaxFrames, "frames", warn);
}

int32_t read_group_count(ByteReader& in, const std::string& owner) {
    const size_t at = in.tell();
    int32_t count = in.i32();
    if (count <= 0) {
        in.fail_at(at, owner + " group count must be positive, is " + std::to_string(count));
    }
    return count;
}

std::vector<uint8_t> read_image(ByteReader& in, size_t image_bytes) {
    auto pixels = in.bytes(image_bytes);
    return std::vector<uint8_t>(pixels.begin(), pixels.end());
}

MdlSkin read_skin(ByteReader& in, const MdlHeader& h, size_t index,
                  std::vector<std::string>& warnings) {
    const std::string owner = "skin " + std::to_string(index);
    const size_t image_bytes = size_t(h.skin_width) * size_t(h.skin_height);
    const size_t type_at = in.tell();
    const int32_t type = in.i32();
    MdlSkin skin;
    if (type == 0) {
        skin.images.push_back(read_image(in, image_bytes));
        return skin;
    }
    if (type != 1) in.fail_at(type_at, owner + " has unknown type " + std::to_string(type));
    skin.is_group = true;
    const int32_t count = read_group_count(in, owner);
    in.require_records(count, 4 + image_bytes, owner + " group (interval + image each)");
    skin.intervals = read_animation_intervals(in, count, owner, warnings);
    for (int32_t i = 0; i < count; ++i) skin.images.push_back(read_image(in, image_bytes));
    return skin;
}

void read_skins(ByteReader& in, Mdl& mdl) {
    const MdlHeader& h = mdl.header;
    // Width and height are int32s that fit the file (checked next), so the product fits 64 bits.
    const uint64_t image_bytes = uint64_t(h.skin_width) * uint64_t(h.skin_height);
    in.require_records(h.num_skins, 4 + image_bytes, "skins (type + image each)");
    mdl.skins.reserve(size_t(h.num_skins));
    for (int32_t i = 0; i < h.num_skins; ++i) {
        mdl.skins.push_back(read_skin(in, h, size_t(i), mdl.warnings));
    }
}

void read_tex_coords(ByteReader& in, Mdl& mdl, Tally& tally) {
    const MdlHeader& h = mdl.header;
    in.require_records(h.num_verts, kTexCoordBytes, "texture coordinates");
    mdl.tex_coords.resize(size_t(h.num_verts));
    for (size_t i = 0; i < mdl.tex_coords.size(); ++i) {
        MdlTexCoord& st = mdl.tex_coords[i];
        st.on_seam = in.i32();
        st.s = in.i32();
        st.t = in.i32();
        if (st.s < 0 || st.s > h.skin_width || st.t < 0 || st.t > h.skin_height) {
            if (tally.tex_coords_outside_skin++ == 0) tally.first_tex_coord_outside = int64_t(i);
        }
    }
}

void read_triangles(ByteReader& in, Mdl& mdl) {
    const int32_t num_verts = mdl.header.num_verts;
    in.require_records(mdl.header.num_tris, kTriangleBytes, "triangles");
    mdl.triangles.resize(size_t(mdl.header.num_tris));
    for (size_t i = 0; i < mdl.triangles.size(); ++i) {
        MdlTriangle& tri = mdl.triangles[i];
        tri.faces_front = in.i32();
        for (size_t k = 0; k < 3; ++k) {
            const size_t at = in.tell();
            tri.vertices[k] = in.i32();
            if (tri.vertices[k] < 0 || tri.vertices[k] >= num_verts) {
                in.fail_at(at, "triangle " + std::to_string(i) + " vertex " + std::to_string(k) +
                                   " index " + std::to_string(tri.vertices[k]) +
                                   " is out of range (model has " + std::to_string(num_verts) +
                                   " vertices)");
            }
        }
    }
}

TriVertex read_tri_vertex(ByteReader& in, Tally& tally) {
    TriVertex tv;
    for (uint8_t& c : tv.v) c = in.u8();
    tv.light_normal_index = in.u8();
    if (tv.light_normal_index >= kNumVertexNormals) {
        tv.light_normal_index = kNumVertexNormals - 1;
        ++tally.normals_clamped;
    }
    return tv;
}

MdlPose read_pose(ByteReader& in, int32_t num_verts, Tally& tally) {
    MdlPose pose;
    pose.bbox_min = read_tri_vertex(in, tally);
    pose.bbox_max = read_tri_vertex(in, tally);
    pose.name = in.fixed_string(kFrameNameBytes);
    in.require_records(num_verts, kTriVertexBytes, "pose '" + pose.name + "' vertices");
    pose.vertices.resize(size_t(num_verts));
    for (TriVertex& tv : pose.vertices) tv = read_tri_vertex(in, tally);
    return pose;
}

MdlFrame read_frame(ByteReader& in, const MdlHeader& h, size_t index, Tally& tally,
                    std::vector<std::string>& warnings) {
    const std::string owner = "frame " + std::to_string(index);
    const size_t type_at = in.tell();
    const int32_t type = in.i32();
    MdlFrame frame;
    if (type == 0) {
        frame.poses.push_back(read_pose(in, h.num_verts, tally));
        return frame;
    }
    if (type != 1) in.fail_at(type_at, owner + " has unknown type " + std::to_string(type));
    frame.is_group = true;
    const int32_t count = read_group_count(in, owner);
    frame.group_bbox_min = read_tri_vertex(in, tally);
    frame.group_bbox_max = read_tri_vertex(in, tally);
    const uint64_t pose_bytes = kPoseHeaderBytes + kTriVertexBytes * uint64_t(h.num_verts);
    in.require_records(count, 4 + pose_bytes, owner + " group (interval + pose each)");
    frame.intervals = read_animation_intervals(in, count, owner, warnings);
    frame.poses.reserve(size_t(count));
    for (int32_t i = 0; i < count; ++i) frame.poses.push_back(read_pose(in, h.num_verts, tally));
    return frame;
}

void read_frames(ByteReader& in, Mdl& mdl, Tally& tally) {
    // validate_header bounded num_frames by the file size, so reserving is safe.
    mdl.frames.reserve(size_t(mdl.header.num_frames));
    for (int32_t i = 0; i < mdl.header.num_frames; ++i) {
        mdl.frames.push_back(read_frame(in, mdl.header, size_t(i), tally, mdl.warnings));
    }
}

void report_tally(const Mdl& mdl, const Tally& tally, std::vector<std::string>& warnings) {
    if (tally.tex_coords_outside_skin > 0) {
        warnings.push_back(std::to_string(tally.tex_coords_outside_skin) +
                           " texture coordinate(s) lie outside the " +
                           std::to_string(mdl.header.skin_width) + "x" +
                           std::to_string(mdl.header.skin_height) + " skin (first: vertex " +
                           std::to_string(tally.first_tex_coord_outside) + ")");
    }
    if (tally.normals_clamped > 0) {
        warnings.push_back(std::to_string(tally.normals_clamped) +
                           " light normal index(es) >= 162 clamped to 161");
    }
}

// Some editors append their own block (LibreQuake models carry "QMEX"); engines ignore it.
void note_trailing_data(const ByteReader& in, std::span<const uint8_t> data, Mdl& mdl) {
    mdl.data_end = in.absolute(in.tell());
    mdl.trailing_bytes = in.remaining();
    if (mdl.trailing_bytes == 0) return;
    auto rest = data.subspan(in.tell());
    const bool qmex = rest.size() >= 4 && std::equal(rest.begin(), rest.begin() + 4, "QMEX");
    mdl.warnings.push_back(std::to_string(mdl.trailing_bytes) +
                           " trailing byte(s) after the last frame at offset " +
                           std::to_string(mdl.data_end) +
                           (qmex ? " (a \"QMEX\" editor block; ignored)" : " (ignored)"));
}

Mdl parse_mdl_body(std::span<const uint8_t> data, const std::string& name) {
    ByteReader in(data, name);
    Mdl mdl;
    mdl.header = read_header(in, mdl.warnings);
    validate_header(in, mdl.header, mdl.warnings);
    Tally tally;
    read_skins(in, mdl);
    read_tex_coords(in, mdl, tally);
    read_triangles(in, mdl);
    read_frames(in, mdl, tally);
    report_tally(mdl, tally, mdl.warnings);
    note_trailing_data(in, data, mdl);
    return mdl;
}

}  // namespace

Result<Mdl> parse_mdl(std::span<const uint8_t> data, const std::string& name) {
    return capture_errors(name, [&] { return parse_mdl_body(data, name); });
}

Vec3 decode_vertex(const MdlHeader& header, const TriVertex& vertex) {
    Vec3 p;
    for (size_t i = 0; i < 3; ++i) p[i] = header.scale[i] * vertex.v[i] + header.scale_origin[i];
    return p;
}

std::vector<Vec3> decoded_positions(const MdlHeader& header, const MdlPose& pose) {
    std::vector<Vec3> out;
    out.reserve(pose.vertices.size());
    for (const TriVertex& tv : pose.vertices) out.push_back(decode_vertex(header, tv));
    return out;
}

bool Bounds::contains(const Vec3& p, float epsilon) const {
    for (size_t i = 0; i < 3; ++i) {
        if (p[i] < min[i] - epsilon || p[i] > max[i] + epsilon) return false;
    }
    return true;
}

namespace {

// Grows `b` by the decoded box of a stored (min, max) pair. A negative scale flips an axis,
// so both corners are taken component-wise.
void include_box(Bounds& b, bool& empty, const MdlHeader& h, const TriVertex& lo,
                 const TriVertex& hi) {
    const Vec3 a = decode_vertex(h, lo);
    const Vec3 c = decode_vertex(h, hi);
    for (size_t i = 0; i < 3; ++i) {
        const float low = std::min(a[i], c[i]);
        const float high = std::max(a[i], c[i]);
        b.min[i] = empty ? low : std::min(b.min[i], low);
        b.max[i] = empty ? high : std::max(b.max[i], high);
    }
    empty = false;
}

}  // namespace

Bounds decoded_frame_bounds(const Mdl& mdl) {
    Bounds b;
    bool empty = true;
    for (const MdlFrame& frame : mdl.frames) {
        if (frame.is_group) {
            include_box(b, empty, mdl.header, frame.group_bbox_min, frame.group_bbox_max);
        }
        for (const MdlPose& pose : frame.poses) {
            include_box(b, empty, mdl.header, pose.bbox_min, pose.bbox_max);
        }
    }
    return b;
}

std::vector<std::string> mdl_flag_names(int32_t flags) {
    static constexpr std::pair<int32_t, const char*> kNames[] = {
        {kEfRocket, "rocket"},   {kEfGrenade, "grenade"}, {kEfGib, "gib"},
        {kEfRotate, "rotate"},   {kEfTracer, "tracer"},   {kEfZomGib, "zomgib"},
        {kEfTracer2, "tracer2"}, {kEfTracer3, "tracer3"},
    };
    std::vector<std::string> names;
    uint32_t rest = static_cast<uint32_t>(flags);
    for (const auto& [bit, label] : kNames) {
        if (rest & uint32_t(bit)) names.emplace_back(label);
        rest &= ~uint32_t(bit);
    }
    for (uint32_t bit = 1; rest != 0; bit <<= 1) {
        if (!(rest & bit)) continue;
        char buf[16];
        std::snprintf(buf, sizeof buf, "0x%x", bit);
        names.emplace_back(buf);
        rest &= ~bit;
    }
    return names;
}

const char* sync_type_name(int32_t sync_type) {
    switch (sync_type) {
        case 0:
            return "sync";
        case 1:
            return "rand";
        default:
            return "unknown";
    }
}

float read_informational_float(ByteReader& in, const char* what,
                               std::vector<std::string>& warnings) {
    float f = in.f32();
    if (std::isfinite(f)) return f;
    warnings.push_back(std::string(what) + " is NaN or infinite (treated as 0)");
    return 0;
}

std::vector<float> read_animation_intervals(ByteReader& in, int32_t count, const std::string& owner,
                                            std::vector<std::string>& warnings) {
    const size_t at = in.tell();
    in.require_records(count, 4, owner + " intervals");
    std::vector<float> intervals(size_t(count), 0.0f);
    for (float& f : intervals) f = in.f32();
    if (size_t fixed = repair_intervals(intervals); fixed > 0) {
        warnings.push_back(owner + ": " + std::to_string(fixed) + " interval(s) at offset " +
                           std::to_string(in.absolute(at)) +
                           " not positive and increasing (repaired)");
    }
    return intervals;
}

size_t repair_intervals(std::vector<float>& intervals) {
    size_t fixed = 0;
    float previous = 0;
    for (float& f : intervals) {
        if (!(std::isfinite(f) && f > previous)) {
            f = previous + kRepairedIntervalStep;
            ++fixed;
        }
        previous = f;
    }
    return fixed;
}

}  // namespace nq
