// Brush models as the renderer ABI sees them: every LibreQuake map's surfaces checked against
// the raw BSP29 lumps read here independently (counts, polygons via edges, planes and sides,
// texel bounds recomputed in double precision, lightmap ranges), winding and plane facts,
// texture flags and animation chains of start.bsp, and RGB lighting (grey and .lit).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "render/brush_model.h"
#include "support/render_test_support.h"
#include "support/synth_bsp.h"

namespace nq {
namespace {

using render_test::raw_f32;
using render_test::raw_i16;
using render_test::raw_i32;

// The BSP29 lumps this test needs, read straight from the file by the documented layout.
struct RawBsp {
    std::vector<uint8_t> b;
    size_t lump_offset(int lump) const { return size_t(raw_i32(b, 4 + 8 * lump)); }
    size_t lump_count(int lump, size_t record) const {
        return size_t(raw_i32(b, 8 + 8 * lump)) / record;
    }
    size_t faces() const { return lump_count(7, 20); }
    size_t face_at(size_t f) const { return lump_offset(7) + 20 * f; }
    uint32_t face_plane(size_t f) const { return uint16_t(raw_i16(b, face_at(f))); }
    bool face_back(size_t f) const { return raw_i16(b, face_at(f) + 2) != 0; }
    int32_t face_first_edge(size_t f) const { return raw_i32(b, face_at(f) + 4); }
    int32_t face_num_edges(size_t f) const { return raw_i16(b, face_at(f) + 8); }
    int32_t face_texinfo(size_t f) const { return raw_i16(b, face_at(f) + 10); }
    uint8_t face_style(size_t f, int k) const { return b[face_at(f) + 12 + k]; }
    int32_t face_lightofs(size_t f) const { return raw_i32(b, face_at(f) + 16); }
    float plane_normal(uint32_t p, int i) const {
        return raw_f32(b, lump_offset(1) + 20 * p + 4 * i);
    }
    float plane_dist(uint32_t p) const { return raw_f32(b, lump_offset(1) + 20 * p + 12); }
    float vertex(uint32_t v, int i) const { return raw_f32(b, lump_offset(3) + 12 * v + 4 * i); }
    uint32_t edge_vertex(uint32_t e, int i) const {
        return uint16_t(raw_i16(b, lump_offset(12) + 4 * e + 2 * i));
    }
    int32_t surfedge(size_t i) const { return raw_i32(b, lump_offset(13) + 4 * i); }
    float texinfo_vec(int32_t t, int axis, int i) const {
        return raw_f32(b, lump_offset(6) + 40 * size_t(t) + 16 * axis + 4 * i);
    }
    int32_t texinfo_miptex(int32_t t) const {
        return raw_i32(b, lump_offset(6) + 40 * size_t(t) + 32);
    }
    size_t lighting_bytes() const { return size_t(raw_i32(b, 8 + 8 * 8)); }
    // The stored (clockwise) polygon of a face, as BSP vertex ids.
    std::vector<uint32_t> polygon(size_t f) const {
        std::vector<uint32_t> ids;
        for (int32_t k = 0; k < face_num_edges(f); ++k) {
            const int32_t e = surfedge(size_t(face_first_edge(f) + k));
            ids.push_back(e >= 0 ? edge_vertex(uint32_t(e), 0) : edge_vertex(uint32_t(-e), 1));
        }
        return ids;
    }
};

struct LoadedMap {
    std::string path;
    RawBsp raw;
    std::shared_ptr<const BrushModelData> data;
};

const std::vector<LoadedMap>& all_maps() {
    static const std::vector<LoadedMap> maps = [] {
        std::vector<LoadedMap> out;
        for (const std::string& path : render_test::all_map_paths()) {
            out.push_back(
                {path, RawBsp{render_test::lq1_bytes(path)}, render_test::load_map(path)});
        }
        return out;
    }();
    return maps;
}

const LoadedMap& start_map() {
    for (const LoadedMap& m : all_maps()) {
        if (m.path == "maps/start.bsp") return m;
    }
    throw std::runtime_error("maps/start.bsp missing");
}

glm::dvec3 position(const nqr_brush_model& brush, uint32_t i) {
    return {brush.positions[3 * i], brush.positions[3 * i + 1], brush.positions[3 * i + 2]};
}

const nqr_surface& surface(const nqr_brush_model& brush, uint32_t i) {
    return *nqr_at(nqr_surface, brush.surfaces, i);
}

TEST(RenderBrushModel, AllMapsHaveOneSurfaceOfTheRightSizePerFace) {
    ASSERT_GE(all_maps().size(), 16u);
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        EXPECT_EQ(brush.size, sizeof(nqr_brush_model));
        ASSERT_EQ(brush.num_surfaces, m.raw.faces()) << m.path;
        uint32_t vertices = 0;
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            EXPECT_EQ(s.size, sizeof(nqr_surface));
            EXPECT_EQ(s.first_vertex, vertices) << m.path << " surface " << i;
            EXPECT_EQ(s.num_vertices, uint32_t(m.raw.face_num_edges(i)));
            vertices += s.num_vertices;
        }
        EXPECT_EQ(brush.num_vertices, vertices);
    }
}

TEST(RenderBrushModel, PolygonsAreTheFaceEdgesReversedToCounterClockwise) {
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            const std::vector<uint32_t> stored = m.raw.polygon(i);
            ASSERT_EQ(stored.size(), s.num_vertices);
            for (uint32_t k = 0; k < s.num_vertices; ++k) {
                const uint32_t expected = stored[(stored.size() - k) % stored.size()];
                const uint32_t at = s.first_vertex + k;
                ASSERT_EQ(brush.vertex_ids[at], expected) << m.path << " surface " << i;
                for (int c = 0; c < 3; ++c) {
                    ASSERT_EQ(brush.positions[3 * at + c], m.raw.vertex(expected, c));
                }
            }
        }
    }
}

TEST(RenderBrushModel, VerticesLieOnThePlaneAndWindingFacesTheNormal) {
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            const uint32_t p = m.raw.face_plane(i);
            const double sign = m.raw.face_back(i) ? -1 : 1;
            const glm::dvec3 n(s.normal[0], s.normal[1], s.normal[2]);
            const glm::dvec3 raw_normal(m.raw.plane_normal(p, 0), m.raw.plane_normal(p, 1),
                                        m.raw.plane_normal(p, 2));
            ASSERT_NEAR(glm::length(n), 1.0, 1e-5) << m.path << " surface " << i;
            if (std::fabs(glm::length(raw_normal) - 1) < 0.01) {  // else derived, see below
                for (int c = 0; c < 3; ++c) {
                    ASSERT_EQ(s.normal[c], float(sign * m.raw.plane_normal(p, c)));
                }
                ASSERT_EQ(s.dist, float(sign * m.raw.plane_dist(p)));
            }
            ASSERT_EQ((s.flags & NQR_SURFACE_PLANE_BACK) != 0, m.raw.face_back(i));
            glm::dvec3 newell(0.0);
            for (uint32_t k = 0; k < s.num_vertices; ++k) {
                const glm::dvec3 a = position(brush, s.first_vertex + k);
                const glm::dvec3 b = position(brush, s.first_vertex + (k + 1) % s.num_vertices);
                ASSERT_LT(std::fabs(glm::dot(n, a) - s.dist), 0.01) << m.path << " surface " << i;
                newell += glm::cross(a, b);
            }
            // Counter-clockwise seen from the front: the right-hand rule gives the normal.
            if (glm::length(newell) > 1e-6) {
                EXPECT_GT(glm::dot(glm::normalize(newell), n), 0.99) << m.path << " surface " << i;
            }
        }
    }
}

// b_exbox2.bsp's face 1 lies on a plane stored with normal (0, 0, 0): the -X side of a box
// spanning x = 0..32, so its outward normal is -X.
TEST(RenderBrushModel, PlaneWithoutNormalGetsThePolygonsNormalAndAWarning) {
    for (const LoadedMap& m : all_maps()) {
        if (m.path != "maps/b_exbox2.bsp") continue;
        const uint32_t p = m.raw.face_plane(1);
        ASSERT_EQ(m.raw.plane_normal(p, 0), 0.0f);
        ASSERT_EQ(m.raw.plane_normal(p, 2), 0.0f);
        const nqr_surface& s = surface(m.data->abi(), 1);
        EXPECT_NEAR(s.normal[0], -1.0f, 1e-6f);
        EXPECT_NEAR(s.normal[1], 0.0f, 1e-6f);
        EXPECT_NEAR(s.normal[2], 0.0f, 1e-6f);
        EXPECT_NEAR(s.dist, 0.0f, 1e-6f);
        bool warned = false;
        for (const std::string& w : m.data->warnings()) {
            warned |= w.find("1 faces lie on planes without a unit normal") != std::string::npos;
        }
        EXPECT_TRUE(warned);
        return;
    }
    FAIL() << "maps/b_exbox2.bsp missing";
}

TEST(RenderBrushModel, TextureAxesTextureIndexAndStylesComeFromTheFace) {
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            const int32_t ti = m.raw.face_texinfo(i);
            for (int c = 0; c < 4; ++c) {
                ASSERT_EQ(s.tex_s[c], m.raw.texinfo_vec(ti, 0, c));
                ASSERT_EQ(s.tex_t[c], m.raw.texinfo_vec(ti, 1, c));
            }
            ASSERT_EQ(s.texture, m.raw.texinfo_miptex(ti));
            for (int k = 0; k < 4; ++k) ASSERT_EQ(s.styles[k], m.raw.face_style(i, k));
        }
    }
}

// Quake's rule recomputed: texel coordinates of every vertex (double precision), bounds snapped
// outwards to multiples of 16.
TEST(RenderBrushModel, TextureMinsAndExtentsMatchAnIndependentComputation) {
    size_t checked = 0;
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            const int32_t ti = m.raw.face_texinfo(i);
            for (int axis = 0; axis < 2; ++axis) {
                double lo = 1e30, hi = -1e30;
                for (uint32_t v : m.raw.polygon(i)) {
                    double st = m.raw.texinfo_vec(ti, axis, 3);
                    for (int c = 0; c < 3; ++c) {
                        st += double(m.raw.vertex(v, c)) * m.raw.texinfo_vec(ti, axis, c);
                    }
                    lo = std::min(lo, st);
                    hi = std::max(hi, st);
                }
                const int32_t mins = int32_t(std::floor(lo / 16)) * 16;
                const int32_t extent = int32_t(std::ceil(hi / 16)) * 16 - mins;
                ASSERT_EQ(s.texture_mins[axis], mins) << m.path << " surface " << i;
                ASSERT_EQ(s.extents[axis], extent) << m.path << " surface " << i;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 8000u);
}

TEST(RenderBrushModel, LightmapRangesLieWithinTheLighting) {
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        EXPECT_EQ(brush.num_light_samples, m.raw.lighting_bytes()) << m.path;
        for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
            const nqr_surface& s = surface(brush, i);
            int styles = 0;
            while (styles < 4 && s.styles[styles] != 255) ++styles;
            if (s.flags & (NQR_SURFACE_SKY | NQR_SURFACE_LIQUID)) {
                EXPECT_EQ(s.light_offset, -1) << m.path << " surface " << i;
            }
            if (s.light_offset < 0) continue;
            EXPECT_EQ(s.light_offset, m.raw.face_lightofs(i));
            const size_t samples = size_t(s.extents[0] / 16 + 1) * size_t(s.extents[1] / 16 + 1);
            EXPECT_LE(size_t(s.light_offset) + samples * size_t(styles), brush.num_light_samples)
                << m.path << " surface " << i;
        }
    }
}

TEST(RenderBrushModel, GreyLightingIsExpandedToRgb) {
    for (const LoadedMap& m : all_maps()) {
        const nqr_brush_model& brush = m.data->abi();
        const size_t base = m.raw.lump_offset(8);
        ASSERT_NE(brush.lighting_rgb, nullptr);
        for (size_t i = 0; i < brush.num_light_samples; ++i) {
            for (int c = 0; c < 3; ++c) ASSERT_EQ(brush.lighting_rgb[3 * i + c], m.raw.b[base + i]);
        }
        EXPECT_FALSE(m.data->has_coloured_light());
    }
}

int32_t texture_named(const nqr_brush_model& brush, const std::string& name) {
    for (uint32_t i = 0; i < brush.num_textures; ++i) {
        if (name == nqr_at(nqr_texture, brush.textures, i)->name) return int32_t(i);
    }
    return -1;
}

TEST(RenderBrushModel, StartMapTexturesCarryFlagsPixelsAndSurfacesFollowThem) {
    const LoadedMap& m = start_map();
    const nqr_brush_model& brush = m.data->abi();
    const Bsp& bsp = m.data->bsp();
    ASSERT_EQ(brush.num_textures, bsp.textures.size());
    for (uint32_t i = 0; i < brush.num_textures; ++i) {
        const nqr_texture& t = *nqr_at(nqr_texture, brush.textures, i);
        EXPECT_EQ(t.size, sizeof(nqr_texture));
        EXPECT_EQ(t.width, bsp.textures[i].width);
        for (int level = 0; level < 4; ++level) {
            EXPECT_EQ(t.mips[level], bsp.textures[i].mips[level].pixels.data());
        }
        const std::string name = t.name;
        EXPECT_EQ((t.flags & NQR_TEXTURE_SKY) != 0, name.rfind("sky", 0) == 0) << name;
        EXPECT_EQ((t.flags & NQR_TEXTURE_LIQUID) != 0, name[0] == '*') << name;
        EXPECT_EQ((t.flags & NQR_TEXTURE_MISSING) != 0, bsp.textures[i].placeholder) << name;
    }
    const int32_t sky = texture_named(brush, "sky1"), tele = texture_named(brush, "*tele1");
    ASSERT_GE(sky, 0);
    ASSERT_GE(tele, 0);
    int sky_surfaces = 0, tele_surfaces = 0;
    for (uint32_t i = 0; i < brush.num_surfaces; ++i) {
        const nqr_surface& s = surface(brush, i);
        EXPECT_EQ((s.flags & NQR_SURFACE_SKY) != 0, s.texture == sky);
        EXPECT_EQ((s.flags & NQR_SURFACE_LIQUID) != 0, s.texture == tele);
        sky_surfaces += s.texture == sky;
        tele_surfaces += s.texture == tele;
    }
    EXPECT_GT(sky_surfaces, 0);
    EXPECT_GT(tele_surfaces, 0);
}

std::vector<std::string> chain_names(const nqr_brush_model& brush, const int32_t* frames,
                                     uint32_t count) {
    std::vector<std::string> names;
    for (uint32_t i = 0; i < count; ++i) {
        names.push_back(nqr_at(nqr_texture, brush.textures, frames[i])->name);
    }
    return names;
}

// start.bsp holds +0terminal/+1terminal, +0button3/+1button3/+abutton3, +0button1/+abutton1
// and +0button2/+1button2/+abutton2.
TEST(RenderBrushModel, StartMapAnimationChains) {
    const nqr_brush_model& brush = start_map().data->abi();
    using Names = std::vector<std::string>;
    const std::map<std::string, std::pair<Names, Names>> expected = {
        {"+0terminal", {{"+0terminal", "+1terminal"}, {}}},
        {"+1terminal", {{"+0terminal", "+1terminal"}, {}}},
        {"+0button3", {{"+0button3", "+1button3"}, {"+abutton3"}}},
        {"+1button3", {{"+0button3", "+1button3"}, {"+abutton3"}}},
        {"+abutton3", {{"+abutton3"}, {"+0button3", "+1button3"}}},
        {"+0button1", {{"+0button1"}, {"+abutton1"}}},
        {"+abutton1", {{"+abutton1"}, {"+0button1"}}},
        {"+0button2", {{"+0button2", "+1button2"}, {"+abutton2"}}},
        {"+1button2", {{"+0button2", "+1button2"}, {"+abutton2"}}},
        {"+abutton2", {{"+abutton2"}, {"+0button2", "+1button2"}}},
    };
    for (uint32_t i = 0; i < brush.num_textures; ++i) {
        const nqr_texture& t = *nqr_at(nqr_texture, brush.textures, i);
        const auto it = expected.find(t.name);
        if (it == expected.end()) {
            EXPECT_EQ(t.num_anim_frames, 0u) << t.name;
            EXPECT_EQ(t.num_alt_anim_frames, 0u) << t.name;
            continue;
        }
        EXPECT_EQ(chain_names(brush, t.anim_frames, t.num_anim_frames), it->second.first) << t.name;
        EXPECT_EQ(chain_names(brush, t.alt_anim_frames, t.num_alt_anim_frames), it->second.second)
            << t.name;
    }
    for (const auto& [name, chains] : expected) EXPECT_NE(texture_named(brush, name), -1) << name;
}

// ---- Coloured light from a .lit file, on the synthetic box room ----------------------------

std::vector<uint8_t> lit_file(size_t samples, uint8_t seed) {
    std::vector<uint8_t> lit = {'Q', 'L', 'I', 'T', 1, 0, 0, 0};
    for (size_t i = 0; i < samples * 3; ++i) lit.push_back(uint8_t(seed + i * 7));
    return lit;
}

Bsp box_room() {
    auto bsp = parse_bsp(test::write_bsp(test::make_box_room(), BspFormat::bsp29), "box.bsp");
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return std::move(*bsp);
}

TEST(RenderBrushModel, MatchingLitFileGivesTheColouredSamples) {
    Bsp bsp = box_room();
    const size_t samples = bsp.lighting.size();
    ASSERT_GT(samples, 0u);
    const std::vector<uint8_t> lit = lit_file(samples, 3);
    auto data = BrushModelData::build(std::move(bsp), lit, "box.lit");
    EXPECT_TRUE(data->has_coloured_light());
    ASSERT_EQ(data->abi().num_light_samples, samples);
    for (size_t i = 0; i < samples * 3; ++i) {
        ASSERT_EQ(data->abi().lighting_rgb[i], uint8_t(3 + i * 7));
    }
}

TEST(RenderBrushModel, MismatchedOrBrokenLitFileFallsBackToGreyWithAWarning) {
    for (const std::vector<uint8_t>& lit :
         {lit_file(5, 1), std::vector<uint8_t>{'N', 'O', 'P', 'E', 1, 0, 0, 0}}) {
        Bsp bsp = box_room();
        const std::vector<uint8_t> grey = bsp.lighting;
        auto data = BrushModelData::build(std::move(bsp), lit, "box.lit");
        EXPECT_FALSE(data->has_coloured_light());
        ASSERT_EQ(data->abi().num_light_samples, grey.size());
        for (size_t i = 0; i < grey.size(); ++i) {
            ASSERT_EQ(data->abi().lighting_rgb[3 * i + 1], grey[i]);
        }
        bool warned = false;
        for (const std::string& w : data->warnings())
            warned |= w.find("box.lit") != std::string::npos;
        EXPECT_TRUE(warned);
    }
}

TEST(RenderBrushModel, LitNameFollowsTheMapName) {
    EXPECT_EQ(lit_name_for("maps/e1m1.bsp"), "maps/e1m1.lit");
    EXPECT_EQ(lit_name_for("maps.dir/start"), "maps.dir/start.lit");
}

}  // namespace
}  // namespace nq
