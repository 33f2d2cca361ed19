#include "support/synth_mdl.h"

#include <cstring>

namespace nq::test {

void LeWriter::u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) out_.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void LeWriter::f32(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u32(bits);
}

void LeWriter::fixed_string(std::string_view s, size_t width) {
    for (size_t i = 0; i < width; ++i) out_.push_back(i < s.size() ? uint8_t(s[i]) : 0);
}

namespace {

int32_t count_or(const std::optional<int32_t>& override_count, size_t actual) {
    return override_count.value_or(static_cast<int32_t>(actual));
}

void write_vertex(LeWriter& w, const SynthMdl::Vertex& v) {
    w.u8(v.x);
    w.u8(v.y);
    w.u8(v.z);
    w.u8(v.normal);
}

void write_header(LeWriter& w, const SynthMdl& m) {
    w.fixed_string(m.ident, 4);
    w.i32(m.version);
    for (float f : m.scale) w.f32(f);
    for (float f : m.scale_origin) w.f32(f);
    w.f32(m.bounding_radius);
    for (float f : m.eye_position) w.f32(f);
    w.i32(count_or(m.num_skins, m.skins.size()));
    w.i32(m.skin_width);
    w.i32(m.skin_height);
    w.i32(count_or(m.num_verts, m.tex_coords.size()));
    w.i32(count_or(m.num_tris, m.triangles.size()));
    w.i32(count_or(m.num_frames, m.frames.size()));
    w.i32(m.sync_type);
    w.i32(m.flags);
    w.f32(m.size);
}

void write_skin(LeWriter& w, const SynthMdl::Skin& s) {
    w.i32(s.type);
    if (s.type == 1) {
        w.i32(count_or(s.group_count, s.images.size()));
        for (float f : s.intervals) w.f32(f);
    }
    for (const auto& image : s.images) w.bytes(image);
}

void write_pose(LeWriter& w, const SynthMdl::Pose& p) {
    write_vertex(w, p.bbox_min);
    write_vertex(w, p.bbox_max);
    w.fixed_string(p.name, 16);
    for (const auto& v : p.vertices) write_vertex(w, v);
}

void write_frame(LeWriter& w, const SynthMdl::Frame& f) {
    w.i32(f.type);
    if (f.type == 1) {
        w.i32(count_or(f.group_count, f.poses.size()));
        write_vertex(w, f.group_bbox_min);
        write_vertex(w, f.group_bbox_max);
        for (float t : f.intervals) w.f32(t);
    }
    for (const auto& p : f.poses) write_pose(w, p);
}

std::vector<uint8_t> skin_image(const SynthMdl& m, uint8_t seed) {
    std::vector<uint8_t> image(size_t(m.skin_width) * size_t(m.skin_height));
    for (size_t i = 0; i < image.size(); ++i) image[i] = static_cast<uint8_t>(seed + i);
    return image;
}

// A pose of the minimal model's 4 vertices, shifted by `dx` (so poses differ).
SynthMdl::Pose quad_pose(const std::string& name, uint8_t dx) {
    SynthMdl::Pose p;
    p.name = name;
    p.vertices = {{uint8_t(10 + dx), 20, 30, 0},
                  {uint8_t(40 + dx), 20, 30, 5},
                  {uint8_t(40 + dx), 60, 30, 100},
                  {uint8_t(10 + dx), 60, 90, 161}};
    p.bbox_min = {uint8_t(10 + dx), 20, 30, 0};
    p.bbox_max = {uint8_t(40 + dx), 60, 90, 0};
    return p;
}

}  // namespace

std::vector<uint8_t> write_mdl(const SynthMdl& m) {
    LeWriter w;
    write_header(w, m);
    for (const auto& s : m.skins) write_skin(w, s);
    for (const auto& st : m.tex_coords) {
        w.i32(st.on_seam);
        w.i32(st.s);
        w.i32(st.t);
    }
    for (const auto& t : m.triangles) {
        w.i32(t.faces_front);
        for (int32_t v : t.vertices) w.i32(v);
    }
    for (const auto& f : m.frames) write_frame(w, f);
    w.bytes(m.trailing);
    return w.take();
}

SynthMdl minimal_mdl() {
    SynthMdl m;
    m.skins.push_back({0, std::nullopt, {}, {skin_image(m, 1)}});
    m.tex_coords = {{0, 0, 0}, {0, 8, 0}, {32, 8, 4}, {0, 0, 4}};
    m.triangles = {{1, {0, 1, 2}}, {0, {0, 2, 3}}};
    SynthMdl::Frame base;
    base.poses.push_back(quad_pose("base", 0));
    m.frames.push_back(base);
    return m;
}

SynthMdl animated_mdl() {
    SynthMdl m = minimal_mdl();
    m.flags = 8 | 16;  // rotate | tracer
    m.sync_type = 1;
    m.skins[0] = {1, std::nullopt, {0.25f, 0.5f}, {skin_image(m, 2), skin_image(m, 3)}};
    m.frames[0].poses[0].name = "stand1";
    SynthMdl::Frame run;
    run.type = 1;
    run.group_bbox_min = {10, 20, 30, 0};
    run.group_bbox_max = {60, 60, 90, 0};
    run.intervals = {0.1f, 0.2f, 0.3f};
    for (uint8_t i = 0; i < 3; ++i)
        run.poses.push_back(quad_pose("run" + std::to_string(i + 1), 10 * i));
    m.frames.push_back(run);
    return m;
}

std::vector<SeedFile> synthetic_mdl_seeds() {
    std::vector<SeedFile> seeds;
    seeds.push_back({"minimal.mdl", write_mdl(minimal_mdl())});
    seeds.push_back({"animated.mdl", write_mdl(animated_mdl())});

    SynthMdl qmex = minimal_mdl();
    qmex.trailing = {'Q', 'M', 'E', 'X', 4, 0, 0, 0, 1, 2, 3, 4};
    seeds.push_back({"qmex_trailer.mdl", write_mdl(qmex)});

    SynthMdl bad_index = minimal_mdl();
    bad_index.triangles[1].vertices[2] = 4;
    seeds.push_back({"bad_triangle_index.mdl", write_mdl(bad_index)});

    SynthMdl lying = animated_mdl();
    lying.num_frames = 3;
    seeds.push_back({"lying_frame_count.mdl", write_mdl(lying)});

    auto truncated = write_mdl(animated_mdl());
    truncated.resize(truncated.size() - 7);
    seeds.push_back({"truncated.mdl", std::move(truncated)});
    return seeds;
}

}  // namespace nq::test
