// The baked ambient cube field: on the synthetic box room with a bright +X wall and a dark -X
// wall, the cube gathered at a point matches the closed-form form factors of the walls (times
// their lightmap level), the blended field is bright on +X and dark on -X as the walls'
// form factors averaged over the samples predict, and it changes smoothly across a leaf
// boundary (a room split in two leafs). A map without lighting gives a uniform cube at Quake's
// full level; malformed leafs bake without crashing; sphere directions and reflectivity are
// checked against their definitions; on LibreQuake maps the bake finishes with finite,
// non-negative, mostly non-uniform cubes (and reports how long e2m3 takes).
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>

#include "render/ambient_cube_field.h"
#include "render/ambient_sample_points.h"
#include "render/light_sampler.h"
#include "render/sphere_directions.h"
#include "render/surface_reflectivity.h"
#include "support/render_test_support.h"
#include "support/synth_bsp.h"

namespace nq {
namespace {

using render_test::normal_lightstyles;

constexpr float kBright = 200.0f;  // lightmap level of the +X wall
constexpr float kDark = 20.0f;     // of the -X wall

PaletteBytes white_palette() {
    PaletteBytes p;
    p.fill(255);
    return p;
}

Bsp parse(const test::SynthBsp& synth) {
    auto bsp = parse_bsp(test::write_bsp(synth, BspFormat::bsp29), "box.bsp");
    if (!bsp) throw std::runtime_error(bsp.error().to_string());
    return std::move(*bsp);
}

// Index of the world face all of whose vertices have coordinate `axis` == value.
uint32_t face_at(const Bsp& bsp, int axis, float value) {
    for (uint32_t f = 0; f < bsp.models[0].num_faces; ++f) {
        const BspFace& face = bsp.faces[f];
        bool all = true;
        for (uint32_t k = 0; k < face.num_surfedges; ++k) {
            const int32_t e = bsp.surfedges[face.first_surfedge + k];
            const uint32_t v = e >= 0 ? bsp.edges[e].v[0] : bsp.edges[-e].v[1];
            all = all && bsp.vertices[v][axis] == value;
        }
        if (all) return f;
    }
    throw std::runtime_error("no such face");
}

// The lightmaps of the world's faces, style 0 (the ceiling's second style is black): the +X
// wall `plus`, the -X wall `minus`, the others `rest`.
void light_walls(Bsp& bsp, float plus, float minus, float rest) {
    for (uint32_t f = 0; f < bsp.models[0].num_faces; ++f) {
        const BspFace& face = bsp.faces[f];
        const size_t samples = face.lightmap_samples();
        const float level = f == face_at(bsp, 0, 128)    ? plus
                            : f == face_at(bsp, 0, -128) ? minus
                                                         : rest;
        const auto first = bsp.lighting.begin() + face.light_offset;
        std::fill_n(first, samples * face.num_styles, uint8_t(0));
        std::fill_n(first, samples, uint8_t(level));
    }
}

// The +X wall kBright, the -X wall kDark, the rest black.
void light_two_walls(Bsp& bsp) {
    light_walls(bsp, kBright, kDark, 0);
}

// The box room split at x = 0 into two leafs: leaf 1 (x >= 0) and a new leaf 2 (x < 0); the
// crate's leaf moves to 3.
test::SynthBsp split_box_room() {
    test::SynthBsp s = test::make_box_room();
    // World nodes 0..5 end in leaf 1 (child -2); the crate's nodes 6..11 use leaf 2 (-3).
    for (size_t n = 6; n < s.nodes.size(); ++n) {
        for (auto& c : s.nodes[n].children) c = c == -3 ? -4 : c;
    }
    const int64_t split = int64_t(s.nodes.size());
    for (auto& c : s.nodes[5].children) c = c == -2 ? split : c;
    test::SynthBsp::Plane plane;
    plane.normal = {1, 0, 0};
    plane.dist = 0;
    s.planes.push_back(plane);
    test::SynthBsp::Node node;
    node.plane = int64_t(s.planes.size() - 1);
    node.children = {-2, -3};  // front (x >= 0): leaf 1; back: leaf 2
    node.mins = test::box_room::kRoomMins;
    node.maxs = test::box_room::kRoomMaxs;
    s.nodes.push_back(node);
    test::SynthBsp::Leaf back = s.leafs[1];
    s.leafs[1].mins[0] = 0;
    back.maxs[0] = 0;
    s.leafs.insert(s.leafs.begin() + 2, back);
    s.models[0].visleafs = 2;
    s.visibility = {0x03};  // each leaf sees both
    return s;
}

struct LitRoom {
    std::shared_ptr<const BrushModelData> data;
    std::vector<glm::vec3> reflectivity;
    explicit LitRoom(test::SynthBsp synth = test::make_box_room(), bool lit = true,
                     void (*light)(Bsp&) = light_two_walls) {
        Bsp bsp = parse(synth);
        if (lit) light(bsp);
        data = BrushModelData::build(std::move(bsp));
        reflectivity = texture_reflectivity(data->bsp(), white_palette());
    }
    const Bsp& bsp() const { return data->bsp(); }
    AmbientGatherer gatherer() const {
        return AmbientGatherer(bsp(), data->lighting_rgb(), reflectivity, {});
    }
    AmbientCubeField field() const {
        return AmbientCubeField::bake(bsp(), data->lighting_rgb(), reflectivity);
    }
};

// Form factor from a point to a rectangle parallel to its surface at distance c, the point's
// normal passing through one corner of the rectangle, sides a and b (radiative transfer's
// classic closed form).
double corner_form_factor(double a, double b, double c) {
    const double x = a / c, y = b / c;
    const double sx = std::sqrt(1 + x * x), sy = std::sqrt(1 + y * y);
    return (x / sx * std::atan(y / sx) + y / sy * std::atan(x / sy)) / (2 * std::numbers::pi);
}

// Form factor from p, facing +axis (sign 1) or -axis (sign -1), to that wall of the room.
double wall_form_factor(const glm::vec3& p, int axis, int sign) {
    const auto& lo = test::box_room::kRoomMins;
    const auto& hi = test::box_room::kRoomMaxs;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const double c = sign > 0 ? hi[axis] - p[axis] : p[axis] - lo[axis];
    const double us[2] = {p[u] - lo[u], hi[u] - p[u]};
    const double vs[2] = {p[v] - lo[v], hi[v] - p[v]};
    double sum = 0;
    for (double a : us) {
        for (double b : vs) sum += corner_form_factor(a, b, c);
    }
    return sum;
}

double x_wall_form_factor(const glm::vec3& p, int sign) {
    return wall_form_factor(p, 0, sign);
}

// ---- definitions --------------------------------------------------------------------------

TEST(RenderSphereDirections, SubdividedIcosahedronCountsAndSpread) {
    for (int level = 0; level <= kMaxSphereLevel; ++level) {
        const auto dirs = sphere_directions(level);
        const size_t faces = 20u << (2 * level);  // 20 * 4^level triangles
        // Euler: V - E + F = 2 with E = 3F / 2.
        EXPECT_EQ(dirs.size(), faces / 2 + 2) << level;
        EXPECT_EQ(int(dirs.size()), sphere_direction_count(level));
        glm::vec3 sum(0);
        for (const glm::vec3& d : dirs) {
            EXPECT_NEAR(glm::length(d), 1.0f, 1e-5f);
            sum += d;
        }
        EXPECT_LT(glm::length(sum), 1e-3f) << "symmetric about the centre";
        // No two directions coincide: the smallest gap is well above zero.
        float closest = 2;
        for (size_t i = 0; i < dirs.size(); ++i) {
            for (size_t j = i + 1; j < dirs.size(); ++j) {
                closest = std::min(closest, glm::length(dirs[i] - dirs[j]));
            }
        }
        EXPECT_GT(closest, 0.5f * std::sqrt(4 * std::numbers::pi_v<float> / dirs.size())) << level;
    }
    EXPECT_EQ(sphere_directions(2).size(), 162u);
    // The coarser set is a prefix of the finer one.
    const auto coarse = sphere_directions(1), fine = sphere_directions(2);
    for (size_t i = 0; i < coarse.size(); ++i) EXPECT_EQ(coarse[i], fine[i]);
}

TEST(RenderSurfaceReflectivity, MeanPaletteColourOfTheTexturePixels) {
    const Bsp bsp = parse(test::make_box_room());
    PaletteBytes palette{};
    for (int i = 0; i < 256; ++i) {
        palette[i * 3] = uint8_t(i);
        palette[i * 3 + 1] = uint8_t(255 - i);
        palette[i * 3 + 2] = 7;
    }
    const auto r = texture_reflectivity(bsp, palette);
    ASSERT_EQ(r.size(), bsp.textures.size());
    for (size_t t = 0; t < bsp.textures.size(); ++t) {
        double sum = 0;
        const uint32_t w = bsp.textures[t].width, h = bsp.textures[t].height;
        for (uint32_t y = 0; y < h; ++y) {
            for (uint32_t x = 0; x < w; ++x) sum += test::synth_texture_pixel(t, 0, x, y);
        }
        const double mean_index = sum / (w * h);
        EXPECT_NEAR(r[t].r, mean_index / 255, 1e-4) << t;
        EXPECT_NEAR(r[t].g, (255 - mean_index) / 255, 1e-4) << t;
        EXPECT_NEAR(r[t].b, 7.0 / 255, 1e-6) << t;
    }
    for (const glm::vec3& c : texture_reflectivity(bsp, std::nullopt)) {
        EXPECT_EQ(c, glm::vec3(kDefaultReflectivity));
    }
}

// ---- the bright and the dark wall ---------------------------------------------------------

// A face of the cube sees only the half of the room in front of it: with every wall but -X at
// one level, the +X face gathers exactly that level, wherever the point is.
TEST(RenderAmbientCube, GatheredFaceSeeingOneLevelGetsExactlyThatLevel) {
    const LitRoom room(test::make_box_room(), true,
                       [](Bsp& bsp) { light_walls(bsp, kBright, kDark, kBright); });
    const AmbientGatherer gatherer = room.gatherer();
    for (const glm::vec3 p : {glm::vec3(0, 0, 32), glm::vec3(40, -30, 0), glm::vec3(-70, 50, 60)}) {
        const AmbientCube cube = gatherer.gather(p);
        EXPECT_NEAR(cube.faces[0].r, kBright, 1e-3f * kBright) << p.x;
        // -X: the dark wall's form factor, the bright rest around it.
        const double f = x_wall_form_factor(p, -1);
        const double minus = kDark * f + kBright * (1 - f);
        EXPECT_NEAR(cube.faces[1].r, minus, 0.1 * minus) << p.x;
        for (int face = 2; face < 6; ++face) {
            EXPECT_GT(cube.faces[face].r, kDark);
            EXPECT_LT(cube.faces[face].r, kBright);
        }
    }
}

// 162 directions resolve a wall's edges only so finely: the gathered light is within 20% of
// the closed-form form factor times the wall's level (the field's blend of several samples
// comes closer, see the next test).
TEST(RenderAmbientCube, GatheredCubeMatchesTheWallsFormFactors) {
    const LitRoom room;
    const AmbientGatherer gatherer = room.gatherer();
    for (const glm::vec3 p : {glm::vec3(0, 0, 32), glm::vec3(40, -30, 0), glm::vec3(-70, 50, 60)}) {
        const AmbientCube cube = gatherer.gather(p);
        const double plus = kBright * x_wall_form_factor(p, 1);
        const double minus = kDark * x_wall_form_factor(p, -1);
        EXPECT_NEAR(cube.faces[0].r, plus, 0.2 * plus) << p.x;
        EXPECT_NEAR(cube.faces[1].g, minus, 0.2 * minus) << p.x;
        EXPECT_EQ(cube.faces[0].r, cube.faces[0].b) << "grey light, white surfaces";
        // Y and Z faces see the x walls only at grazing angles: between the two.
        for (int f = 2; f < 6; ++f) {
            EXPECT_GT(cube.faces[f].r, 0.0f);
            EXPECT_LT(cube.faces[f].r, cube.faces[0].r);
        }
    }
}

TEST(RenderAmbientCube, FieldIsBrightTowardTheBrightWallAsTheSamplesFormFactorsPredict) {
    const LitRoom room;
    const AmbientCubeField field = room.field();
    ASSERT_FALSE(field.empty());
    for (const AmbientSample& s : field.samples()) {
        EXPECT_EQ(leaf_at(room.bsp(), {s.position.x, s.position.y, s.position.z}), s.leaf);
    }
    for (const glm::vec3 p : {glm::vec3(0, 0, 32), glm::vec3(30, 20, -20)}) {
        // Expected: the samples' closed-form cubes, blended by the documented weights.
        double plus = 0, minus = 0, total = 0;
        for (const AmbientSample& s : field.samples()) {
            const double d = glm::length(s.position - p);
            if (d >= kBlendRadius) continue;
            const double x = std::clamp((kBlendRadius - d) / (0.5 * kBlendRadius), 0.0, 1.0);
            const double w = x * x * (3 - 2 * x) / ((d / kBlendScale) * (d / kBlendScale) + 1);
            plus += w * kBright * x_wall_form_factor(s.position, 1);
            minus += w * kDark * x_wall_form_factor(s.position, -1);
            total += w;
        }
        ASSERT_GT(total, 0);
        AmbientCube cube;
        ASSERT_TRUE(field.cube_at(p, cube));
        EXPECT_NEAR(cube.faces[0].r, plus / total, 0.1 * plus / total);
        EXPECT_NEAR(cube.faces[1].r, minus / total, 0.1 * minus / total);
        EXPECT_GT(cube.faces[0].r, 5 * cube.faces[1].r);
    }
}

TEST(RenderAmbientCube, LightSamplerHandsTheFieldsCubeOnWithDynamicLights) {
    const LitRoom room;
    const AmbientCubeField field = room.field();
    LightSampler sampler(room.bsp(), room.data->lighting_rgb(), {}, &field);
    const glm::vec3 p(10, 0, 20);
    AmbientCube cube;
    ASSERT_TRUE(field.cube_at(p, cube));
    EntityLighting light;
    sampler.sample({p}, normal_lightstyles(), {}, light);
    for (int f = 0; f < 6; ++f) EXPECT_FLOAT_EQ(light.ambient_cube[f][1], cube.faces[f].g / 128);
    EXPECT_GT(light.ambient_cube[0][0], 5 * light.ambient_cube[1][0]);
    // A white dynamic light 50 units toward +Y adds (radius - distance) on +Y only.
    nqr_dlight d{sizeof(nqr_dlight), {p.x, p.y + 50, p.z}, 150, {1, 1, 1}};
    sampler.sample({p}, normal_lightstyles(), {&d, 1}, light);
    EXPECT_NEAR(light.ambient_cube[2][0], (cube.faces[2].r + 100) / 128, 1e-4f);
    EXPECT_NEAR(light.ambient_cube[3][0], cube.faces[3].r / 128, 1e-5f);
    EXPECT_NEAR(light.ambient_cube[0][0], cube.faces[0].r / 128, 1e-5f);
}

// Floor and ceiling made sky ("sky1"), the walls black: the +Z face gathers the sky level
// (times the sky texture's colour, white here) over the ceiling's form factor; no sky level,
// no light.
TEST(RenderAmbientCube, SkySendsItsLevelWhereRaysMeetIt) {
    test::SynthBsp synth = test::make_box_room();
    synth.textures[1].name = "sky1";  // the texture of floor and ceiling
    const LitRoom room(synth, true, [](Bsp& bsp) { light_walls(bsp, 0, 0, 0); });
    AmbientBakeSettings settings;
    settings.sky_level = 100;
    const AmbientGatherer gatherer(room.bsp(), room.data->lighting_rgb(), room.reflectivity,
                                   settings);
    const glm::vec3 p(20, -10, 40);
    const AmbientCube cube = gatherer.gather(p);
    const double up = 100 * wall_form_factor(p, 2, 1);
    const double down = 100 * wall_form_factor(p, 2, -1);
    EXPECT_NEAR(cube.faces[4].g, up, 0.2 * up);
    EXPECT_NEAR(cube.faces[5].g, down, 0.2 * down);
    settings.sky_level = 0;
    const AmbientGatherer no_sky(room.bsp(), room.data->lighting_rgb(), room.reflectivity,
                                 settings);
    for (const glm::vec3& face : no_sky.gather(p).faces) EXPECT_EQ(face, glm::vec3(0));
}

// ---- smoothness across a leaf boundary ----------------------------------------------------

TEST(RenderAmbientCube, CubeChangesSmoothlyAcrossALeafBoundary) {
    const LitRoom room(split_box_room());
    ASSERT_EQ(leaf_at(room.bsp(), {10, 0, 0}), 1u);
    ASSERT_EQ(leaf_at(room.bsp(), {-10, 0, 0}), 2u);
    const AmbientCubeField field = room.field();
    // What a cube per leaf would jump by at x = 0: the mean of each leaf's samples.
    glm::vec3 mean[3] = {};
    int count[3] = {};
    for (const AmbientSample& s : field.samples()) {
        ASSERT_TRUE(s.leaf == 1 || s.leaf == 2);
        mean[s.leaf] += s.cube.faces[0];
        ++count[s.leaf];
    }
    ASSERT_GT(count[1], 0);
    ASSERT_GT(count[2], 0);
    const float jump = std::fabs(mean[1].r / count[1] - mean[2].r / count[2]);
    ASSERT_GT(jump, 5.0f);
    float largest_step = 0, previous[6] = {};
    for (int i = 0; i <= 64; ++i) {
        const glm::vec3 p(-32.0f + i, 8.0f, 24.0f);
        AmbientCube cube;
        ASSERT_TRUE(field.cube_at(p, cube));
        for (int f = 0; f < 6; ++f) {
            if (i > 0)
                largest_step = std::max(largest_step, std::fabs(cube.faces[f].r - previous[f]));
            previous[f] = cube.faces[f].r;
        }
    }
    EXPECT_LT(largest_step, 0.05f * jump) << "per 1-unit step; a per-leaf cube jumps " << jump;
}

// ---- degenerate input ---------------------------------------------------------------------

TEST(RenderAmbientCube, UnlitMapGivesQuakesFullLevelOnEveryFace) {
    test::SynthBsp unlit = test::make_box_room();
    unlit.lighting.clear();
    for (auto& f : unlit.faces) f.light_offset = -1;
    const LitRoom room(unlit, false);
    ASSERT_TRUE(room.data->lighting_rgb().empty());
    const AmbientCubeField field = room.field();
    AmbientCube cube;
    ASSERT_TRUE(field.cube_at({0, 0, 0}, cube));
    for (const glm::vec3& face : cube.faces) {
        EXPECT_NEAR(face.r, kUnlitSurfaceLevel, 1e-2f);  // every ray meets a wall, all at 255
    }
    LightSampler sampler(room.bsp(), room.data->lighting_rgb(), {}, &field);
    EntityLighting light;
    sampler.sample({{0, 0, 0}}, normal_lightstyles(), {}, light);
    for (const auto& face : light.ambient_cube) EXPECT_NEAR(face[2], 255.0f / 128, 1e-3f);
}

TEST(RenderAmbientCube, MalformedLeafsAndEmptyMapsBakeWithoutCrashing) {
    Bsp bsp = parse(test::make_box_room());
    light_two_walls(bsp);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const BspLeaf room_leaf = bsp.leafs[1];
    auto add = [&](BspLeaf leaf) { bsp.leafs.insert(bsp.leafs.begin() + 2, leaf); };
    BspLeaf inverted = room_leaf;  // mins above maxs
    std::swap(inverted.mins, inverted.maxs);
    add(inverted);
    BspLeaf not_finite = room_leaf;
    not_finite.mins[1] = nan;
    not_finite.maxs[2] = inf;
    add(not_finite);
    BspLeaf huge = room_leaf;  // a box far larger than the map, marksurfaces out of range
    huge.mins = {-1e30f, -1e30f, -1e30f};
    huge.maxs = {1e30f, 1e30f, 1e30f};
    huge.first_marksurface = 1000000;
    huge.num_marksurfaces = 5000000;
    add(huge);
    BspLeaf flat = room_leaf;  // zero volume, no faces
    flat.maxs = flat.mins;
    flat.num_marksurfaces = 0;
    add(flat);
    BspLeaf odd = room_leaf;
    odd.contents = 7;  // not a contents value
    add(odd);
    bsp.models[0].visleafs = uint32_t(bsp.leafs.size() - 1);
    auto data = BrushModelData::build(std::move(bsp));
    const auto reflectivity = texture_reflectivity(data->bsp(), white_palette());
    const AmbientCubeField field =
        AmbientCubeField::bake(data->bsp(), data->lighting_rgb(), reflectivity);
    for (const AmbientSample& s : field.samples()) {
        for (const glm::vec3& face : s.cube.faces) {
            EXPECT_TRUE(std::isfinite(face.r) && face.r >= 0.0f);
        }
    }
    AmbientCube cube;
    EXPECT_TRUE(field.cube_at({0, 0, 0}, cube));
    (void)field.cube_at({nan, 0, 0}, cube);  // answers anything, but answers
    (void)field.cube_at({1e9f, -1e9f, 1e9f}, cube);

    const Bsp empty;
    EXPECT_TRUE(ambient_sample_points(empty).empty());
    const AmbientCubeField none = AmbientCubeField::bake(empty, {}, {});
    EXPECT_TRUE(none.empty());
    EXPECT_FALSE(none.cube_at({0, 0, 0}, cube));
    EXPECT_EQ(cube.faces[0], glm::vec3(0));
    const AmbientCubeField unbaked;
    EXPECT_FALSE(unbaked.cube_at({0, 0, 0}, cube));
}

// ---- LibreQuake maps -----------------------------------------------------------------------

PaletteBytes lq1_palette() {
    const std::vector<uint8_t> bytes = render_test::lq1_bytes("gfx/palette.lmp");
    PaletteBytes p{};
    if (bytes.size() < p.size()) throw std::runtime_error("short palette");
    std::copy_n(bytes.begin(), p.size(), p.begin());
    return p;
}

TEST(RenderAmbientCube, RealMapsBakeFiniteNonNegativeVaryingCubes) {
    for (const char* path : {"maps/start.bsp", "maps/e2m3.bsp"}) {
        const auto data = render_test::load_map(path);
        const auto reflectivity = texture_reflectivity(data->bsp(), lq1_palette());
        const auto start = std::chrono::steady_clock::now();
        const AmbientCubeField field =
            AmbientCubeField::bake(data->bsp(), data->lighting_rgb(), reflectivity);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::printf("%s: %zu ambient samples baked in %.0f ms\n", path, field.samples().size(),
                    seconds * 1000);
        ASSERT_GT(field.samples().size(), 100u) << path;
        size_t varying = 0;
        for (const AmbientSample& s : field.samples()) {
            float lo = 1e30f, hi = 0;
            for (const glm::vec3& face : s.cube.faces) {
                for (int c = 0; c < 3; ++c) {
                    ASSERT_TRUE(std::isfinite(face[c]) && face[c] >= 0.0f) << path;
                    lo = std::min(lo, face[c]);
                    hi = std::max(hi, face[c]);
                }
            }
            varying += hi - lo > 1e-3f * std::max(hi, 1.0f);
        }
        EXPECT_GT(varying * 2, field.samples().size())
            << path << ": " << varying << " of " << field.samples().size();
    }
}

}  // namespace
}  // namespace nq
