// Entity lighting: exact lightmap samples, styles and the fallback cube on the synthetic box room
// (whose lightmap bytes are known); light entities from entity text; on LibreQuake maps a point
// at a light is brighter than the darkest place far from every light, the direction points at a
// nearby light, and along a path the direction only jumps at rare shadow edges (and never once
// smoothed); dynamic lights, minimum light, fullbright; no allocation per sample.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/entities.h"
#include "render/ambient_cube_field.h"
#include "render/light_entities.h"
#include "render/light_list_smoother.h"
#include "render/light_sampler.h"
#include "render/light_smoother.h"
#include "render/lightmap_probe.h"
#include "render/surface_reflectivity.h"
#include "support/render_test_support.h"
#include "support/allocation_counter.h"
#include "support/synth_bsp.h"

namespace nq {
namespace {

using render_test::normal_lightstyles;

glm::vec3 vec(const float v[3]) {
    return {v[0], v[1], v[2]};
}

std::vector<LightEntity> lights_of(const Bsp& bsp) {
    auto entities = parse_entities(bsp.entities, "entities");
    if (!entities) throw std::runtime_error(entities.error().to_string());
    std::vector<std::string> warnings;
    return find_light_entities(*entities, warnings);
}

// ---- The synthetic box room: floor z = -64, ceiling z = 128, walls at +-128 --------------

struct BoxRoom {
    std::shared_ptr<const BrushModelData> data;
    LightSampler sampler;
    explicit BoxRoom(test::SynthBsp synth = test::make_box_room())
        : data(build(std::move(synth))),
          sampler(data->bsp(), data->lighting_rgb(), lights_of(data->bsp())) {}
    static std::shared_ptr<const BrushModelData> build(test::SynthBsp synth) {
        auto bsp = parse_bsp(test::write_bsp(synth, BspFormat::bsp29), "box.bsp");
        if (!bsp) throw std::runtime_error(bsp.error().to_string());
        return BrushModelData::build(std::move(*bsp));
    }
    // The world face all of whose vertices have coordinate `axis` == value.
    const BspFace& face_at(int axis, float value) const {
        const Bsp& bsp = data->bsp();
        for (uint32_t f = 0; f < bsp.models[0].num_faces; ++f) {
            const BspFace& face = bsp.faces[f];
            bool all = true;
            for (uint32_t k = 0; k < face.num_surfedges; ++k) {
                const int32_t e = bsp.surfedges[face.first_surfedge + k];
                const uint32_t v = e >= 0 ? bsp.edges[e].v[0] : bsp.edges[-e].v[1];
                all = all && bsp.vertices[v][axis] == value;
            }
            if (all) return face;
        }
        throw std::runtime_error("no such face");
    }
    // Lightmap byte of style slot `k`, sample (i, j), of `face` (17 x 17 samples per style).
    float byte(const BspFace& face, int k, int i, int j) const {
        EXPECT_EQ(face.lightmap_width, 17u);
        return data->bsp().lighting[size_t(face.light_offset) + size_t(k) * 17 * 17 + j * 17 + i];
    }
};

// On the floor (s = x, t = -y, texture_mins -128), sample (3, 2) sits at x = -80, y = 96.
TEST(RenderLightSampler, LightPointReadsTheFloorSampleBelow) {
    BoxRoom room;
    const BspFace& floor = room.face_at(2, -64);
    const auto styles = normal_lightstyles();
    const glm::vec3 at = room.sampler.light_point({-80, 96, 0}, styles);
    EXPECT_FLOAT_EQ(at.r, room.byte(floor, 0, 3, 2));
    EXPECT_FLOAT_EQ(at.b, room.byte(floor, 0, 3, 2));
    // Halfway to sample (4, 2): the mean of the two (bilinear).
    const glm::vec3 between = room.sampler.light_point({-72, 96, 0}, styles);
    EXPECT_FLOAT_EQ(between.g, (room.byte(floor, 0, 3, 2) + room.byte(floor, 0, 4, 2)) / 2);
    // The probe reports the hit on the floor.
    const auto hit = first_surface_along(room.data->bsp(), {-80, 96, 0}, {-80, 96, -2048});
    ASSERT_TRUE(hit);
    EXPECT_EQ(&room.data->bsp().faces[hit->face], &floor);
    EXPECT_NEAR(hit->point.z, -64.0f, 1e-3f);
    EXPECT_NEAR(hit->s, 48.0f, 1e-3f);
    EXPECT_NEAR(hit->t, 32.0f, 1e-3f);
}

TEST(RenderLightSampler, LightstylesScaleTheirSamples) {
    BoxRoom room;
    const BspFace& floor = room.face_at(2, -64);
    std::vector<float> styles = normal_lightstyles();
    styles[0] = 2.0f;
    EXPECT_FLOAT_EQ(room.sampler.light_point({-80, 96, 0}, styles).r,
                    2 * room.byte(floor, 0, 3, 2));
    styles[0] = 0.0f;
    EXPECT_FLOAT_EQ(room.sampler.light_point({-80, 96, 0}, styles).r, 0.0f);
}

// Without a baked ambient cube field (render_ambient_cube_test has the field), every face of
// the cube is the level of the floor sample below, styles applied.
TEST(RenderLightSampler, WithoutAFieldTheCubeIsThePointsOwnLevel) {
    BoxRoom room;
    const BspFace& floor = room.face_at(2, -64);
    std::vector<float> styles = normal_lightstyles();
    styles[0] = 0.5f;
    EntityLighting light;
    room.sampler.sample({{-80, 96, 0}}, styles, {}, light);
    EXPECT_EQ(light.size, sizeof(nqr_entity_light));
    for (const auto& face : light.ambient_cube) {
        for (float c : face) EXPECT_FLOAT_EQ(c, 0.5f * room.byte(floor, 0, 3, 2) / 128);
    }
}

TEST(RenderLightSampler, LevelSplitsIntoAmbientAndDirectionalLikeQuake) {
    BoxRoom room;
    const BspFace& floor = room.face_at(2, -64);
    const float level = room.byte(floor, 0, 3, 2);
    for (float scale : {0.25f, 1.0f, 1.6f, 3.0f}) {
        std::vector<float> styles = normal_lightstyles();
        styles[0] = scale;
        EntityLighting light;
        room.sampler.sample({{-80, 96, 0}}, styles, {}, light);
        const float l = level * scale;
        const float ambient = std::min(l, 128.0f);
        EXPECT_FLOAT_EQ(light.ambient, ambient / 128) << l;
        EXPECT_FLOAT_EQ(light.directional, std::min(l, 192 - ambient) / 128) << l;
        EXPECT_LE(light.ambient + light.directional, 1.5f + 1e-6f);
    }
}

TEST(RenderLightSampler, DirectionPointsAtTheRoomsLightAndColourIsWhiteWithoutLit) {
    BoxRoom room;  // one light at (0, 0, 96)
    for (const glm::vec3 p : {glm::vec3(64, 0, 0), glm::vec3(-100, 80, -40), glm::vec3(0, 0, 0)}) {
        EntityLighting light;
        room.sampler.sample({p}, normal_lightstyles(), {}, light);
        const glm::vec3 toward = glm::normalize(glm::vec3(0, 0, 96) - p);
        EXPECT_GT(glm::dot(vec(light.direction), toward), 0.995f) << p.x << " " << p.y;
        EXPECT_NEAR(glm::length(vec(light.direction)), 1.0f, 1e-5f);
        for (float c : light.color) EXPECT_FLOAT_EQ(c, 1.0f);
    }
}

TEST(RenderLightSampler, DarknessWithMinimumLightAndUnlitMapsAndFullbright) {
    BoxRoom room;
    EntityLighting light;
    const glm::vec3 below_the_room(0, 0, -200);  // solid, nothing beneath
    room.sampler.sample({below_the_room}, normal_lightstyles(), {}, light);
    EXPECT_EQ(light.ambient, 0.0f);
    room.sampler.sample({below_the_room, kViewModelMinimumLight}, normal_lightstyles(), {}, light);
    EXPECT_FLOAT_EQ(light.ambient, 24.0f / 128);
    EXPECT_FLOAT_EQ(light.directional, 24.0f / 128);

    test::SynthBsp unlit = test::make_box_room();
    unlit.lighting.clear();
    for (auto& f : unlit.faces) f.light_offset = -1;
    BoxRoom dark_map(unlit);
    dark_map.sampler.sample({{0, 0, 0}}, normal_lightstyles(), {}, light);
    EXPECT_FLOAT_EQ(light.ambient, 1.0f);  // Quake lights everything fully (255)
    EXPECT_FLOAT_EQ(light.directional, 0.5f);

    EntityLightQuery bright{{0, 0, 0}};
    bright.fullbright = true;
    room.sampler.sample(bright, normal_lightstyles(), {}, light);
    EXPECT_FLOAT_EQ(light.ambient, 1.0f);
    EXPECT_FLOAT_EQ(light.directional, 0.0f);
    EXPECT_FLOAT_EQ(light.ambient_cube[3][2], 1.0f);
}

TEST(RenderLightSampler, DynamicLightsAddLevelDirectionAndColour) {
    BoxRoom room;
    std::vector<float> off(64, 0.0f);  // the map's light switched off entirely
    nqr_dlight dlight{sizeof(nqr_dlight), {0, 0, 0}, 100, {1.0f, 0.5f, 0.0f}};
    EntityLighting light;
    room.sampler.sample({{50, 0, 0}}, off, {&dlight, 1}, light);
    EXPECT_FLOAT_EQ(light.ambient, 50.0f / 128);  // radius - distance
    EXPECT_GT(glm::dot(vec(light.direction), glm::vec3(-1, 0, 0)), 0.99f);
    EXPECT_FLOAT_EQ(light.color[1], 0.5f);
    EXPECT_FLOAT_EQ(light.ambient_cube[1][0], 50.0f / 128);  // -X faces the dlight
    EXPECT_FLOAT_EQ(light.ambient_cube[0][0], 0.0f);
    room.sampler.sample({{150, 0, 0}}, off, {&dlight, 1}, light);
    EXPECT_EQ(light.ambient, 0.0f) << "out of the dlight's radius";
}

// ---- Light entities ------------------------------------------------------------------------

TEST(RenderLightEntities, KeysDefaultsAndOddValues) {
    const char* text =
        "{ \"classname\" \"worldspawn\" }\n"
        "{ \"classname\" \"light\" \"origin\" \"0 0 96\" \"light\" \"300\" \"_color\" \"1 0.5 "
        "0.25\" }\n"
        "{ \"classname\" \"light_fluoro\" \"origin\" \"8 8 8\" \"style\" \"5\" \"delay\" \"2\" }\n"
        "{ \"classname\" \"light_torch_small_walltorch\" \"origin\" \"1 2 3\" \"_light\" \"150\" "
        "\"_color\" \"255 128 0\" \"wait\" \"2\" }\n"
        "{ \"classname\" \"light\" \"origin\" \"1 1 1\" \"light\" \"bright\" \"style\" \"99\" }\n"
        "{ \"classname\" \"light\" }\n"
        "{ \"classname\" \"info_player_start\" \"origin\" \"0 0 0\" \"light\" \"500\" }\n";
    auto entities = parse_entities(std::string_view(text), "lights");
    ASSERT_TRUE(entities);
    std::vector<std::string> warnings;
    const auto lights = find_light_entities(*entities, warnings);
    ASSERT_EQ(lights.size(), 4u);
    EXPECT_EQ(lights[0].origin, glm::vec3(0, 0, 96));
    EXPECT_EQ(lights[0].brightness, 300.0f);
    EXPECT_EQ(lights[0].color, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_EQ(lights[0].reach(), 300.0f);
    EXPECT_EQ(lights[1].brightness, kDefaultLightBrightness);
    EXPECT_EQ(lights[1].style, 5u);
    EXPECT_TRUE(std::isinf(lights[1].reach()));
    EXPECT_EQ(lights[2].brightness, 150.0f);
    EXPECT_NEAR(lights[2].color.g, 128.0f / 255, 1e-6f);
    EXPECT_EQ(lights[2].reach(), 75.0f);
    EXPECT_EQ(lights[3].brightness, kDefaultLightBrightness);
    EXPECT_EQ(lights[3].style, 0u);
    ASSERT_EQ(warnings.size(), 3u);  // "bright", style 99, no origin
    EXPECT_NE(warnings[0].find("\"light\" is not a number"), std::string::npos);
    EXPECT_NE(warnings[2].find("no valid origin"), std::string::npos);
}

// ---- LibreQuake maps -----------------------------------------------------------------------

struct RealMap {
    std::shared_ptr<const BrushModelData> data;
    std::vector<LightEntity> lights;
    std::unique_ptr<LightSampler> sampler;
    explicit RealMap(const std::string& path) : data(render_test::load_map(path)) {
        lights = lights_of(data->bsp());
        sampler = std::make_unique<LightSampler>(data->bsp(), data->lighting_rgb(), lights);
    }
    bool open(const glm::vec3& p) const {
        return point_contents(data->bsp(), 0, {p.x, p.y, p.z}) != bsp_contents::solid;
    }
    EntityLighting sample(const glm::vec3& p) const {
        EntityLighting light;
        sampler->sample({p}, normal_lightstyles(), {}, light);
        return light;
    }
    float nearest_light(const glm::vec3& p) const {
        float best = 1e30f;
        for (const LightEntity& l : lights) best = std::min(best, glm::length(l.origin - p));
        return best;
    }
    // Origins of the non-light entities that stand in open space.
    std::vector<glm::vec3> entity_origins() const {
        std::vector<glm::vec3> out;
        auto entities = parse_entities(data->bsp().entities, "entities");
        for (const Entity& e : entities->entities) {
            if (classname(e).rfind("light", 0) == 0) continue;
            if (auto o = find_vec3(e, "origin")) {
                const glm::vec3 p((*o)[0], (*o)[1], (*o)[2]);
                if (open(p)) out.push_back(p);
            }
        }
        return out;
    }
};

float mean(const std::vector<float>& v) {
    float sum = 0;
    for (float x : v) sum += x;
    return v.empty() ? 0.0f : sum / float(v.size());
}

// From the entity lump: the floor right under each light entity, against the indoor entities
// (no sky straight above, so no sunlight) farthest from every light. The first are brighter on
// average, in the light level and in what an entity standing there is lit with.
TEST(RenderLightSampler, UnderTheLightsIsBrighterThanDarkCornersFarFromThem) {
    for (const char* path : {"maps/lqdm4_a6.bsp", "maps/lqdm9_a7.bsp"}) {
        RealMap map(path);
        ASSERT_FALSE(map.lights.empty());
        const auto styles = normal_lightstyles();
        std::vector<float> near_level, near_lit, dark_level, dark_lit;
        for (const LightEntity& l : map.lights) {
            if (!map.open(l.origin)) continue;
            const BspTrace t =
                trace_down(map.data->bsp(), {l.origin.x, l.origin.y, l.origin.z}, 2048);
            const glm::vec3 p(t.end[0], t.end[1], t.end[2] + 8);
            near_level.push_back(map.sampler->light_point(p, styles).r);
            const EntityLighting light = map.sample(p);
            near_lit.push_back(light.ambient + light.directional);
        }
        for (const glm::vec3& p : map.entity_origins()) {
            const auto up =
                first_surface_along(map.data->bsp(), p, p + glm::vec3(0, 0, 4096), true);
            if (map.nearest_light(p) < 200.0f || (up && up->sky)) continue;
            dark_level.push_back(map.sampler->light_point(p, styles).r);
            const EntityLighting light = map.sample(p);
            dark_lit.push_back(light.ambient + light.directional);
        }
        ASSERT_GE(near_level.size(), 5u) << path;
        ASSERT_GE(dark_level.size(), 3u) << path;
        EXPECT_GT(mean(near_level), mean(dark_level) * 1.2f) << path;
        EXPECT_GT(mean(near_lit), mean(dark_lit)) << path;
    }
}

TEST(RenderLightSampler, DirectionPointsTowardANearbyStrongLight) {
    size_t checked = 0;
    for (const char* path : {"maps/start.bsp", "maps/lqdm4_a6.bsp", "maps/lqdm9_a7.bsp"}) {
        RealMap map(path);
        for (const LightEntity& l : map.lights) {
            if (l.brightness < 100 || !map.open(l.origin)) continue;
            // 48 units beside the light, in open space and in plain view of it.
            for (const glm::vec3 offset : {glm::vec3(48, 0, 0), glm::vec3(-48, 0, 0),
                                           glm::vec3(0, 48, 0), glm::vec3(0, -48, 0)}) {
                const glm::vec3 p = l.origin + offset;
                const BspTrace t = trace_hull(map.data->bsp(), 0, {p.x, p.y, p.z},
                                              {l.origin.x, l.origin.y, l.origin.z});
                if (!map.open(p) || t.hit()) continue;
                // Skip places where another light is as near: "the" nearest light is ambiguous.
                bool crowded = false;
                for (const LightEntity& other : map.lights) {
                    crowded |= &other != &l && glm::length(other.origin - p) < 150.0f;
                }
                if (crowded) continue;
                const glm::vec3 dir = vec(map.sample(p).direction);
                EXPECT_GT(glm::dot(dir, -glm::normalize(offset)), 0.8f) << path;
                ++checked;
            }
        }
    }
    EXPECT_GE(checked, 8u);
}

float angle_degrees(const glm::vec3& a, const glm::vec3& b) {
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0f, 1.0f)));
}

// Along paths through the maps in 1-unit steps: the raw direction changes by more than 5
// degrees in very few steps (shadow edges), and the smoothed one - an entity running at
// Quake's 320 units per second - never turns more than pi * dt / tau allows.
TEST(RenderLightSampler, DirectionIsContinuousAlongPathsAndSmoothedNeverJumps) {
    struct Path {
        const char* map;
        glm::vec3 start;
        int axis;
        int length;
    };
    const Path paths[] = {{"maps/lqdm4_a6.bsp", {96, -32, -40}, 1, 400},
                          {"maps/lqdm4_a6.bsp", {-300, -32, -40}, 0, 700},
                          {"maps/start.bsp", {-192, 288, -224}, 1, 300}};
    const float dt = 1.0f / 320.0f;
    const float max_turn = 180.0f * dt / kLightSmoothingSeconds;
    size_t steps = 0, jumps = 0;
    for (const Path& path : paths) {
        RealMap map(path.map);
        LightSmoother smoother;
        glm::vec3 previous_raw(0), previous_smoothed(0);
        for (int i = 0; i < path.length; ++i) {
            glm::vec3 p = path.start;
            p[path.axis] += float(i);
            if (!map.open(p)) {
                previous_raw = glm::vec3(0);
                smoother.reset();
                continue;
            }
            EntityLighting light = map.sample(p);
            const glm::vec3 raw = vec(light.direction);
            smoother.update(light, dt, light);
            const glm::vec3 smoothed = vec(light.direction);
            EXPECT_NEAR(glm::length(smoothed), 1.0f, 1e-4f);
            if (previous_raw != glm::vec3(0)) {
                ++steps;
                jumps += angle_degrees(previous_raw, raw) > 5.0f;
                EXPECT_LE(angle_degrees(previous_smoothed, smoothed), max_turn + 0.01f)
                    << path.map << " step " << i;
            }
            previous_raw = raw;
            previous_smoothed = smoothed;
        }
    }
    EXPECT_GT(steps, 1000u);
    EXPECT_LE(jumps * 100, steps) << jumps << " jumps in " << steps << " steps";
}

TEST(RenderLightSmoother, FirstSamplePassesThenConverges) {
    EntityLighting a{}, b{};
    a.ambient = 0.2f;
    a.direction[2] = 1;
    b.ambient = 1.0f;
    b.direction[0] = 1;
    LightSmoother smoother;
    EntityLighting out;
    smoother.update(a, 0.016f, out);
    EXPECT_EQ(out.ambient, 0.2f);
    EXPECT_EQ(out.size, sizeof(nqr_entity_light));
    smoother.update(b, 0.1f, out);  // one time constant: 63% of the way
    EXPECT_NEAR(out.ambient, 0.2f + 0.8f * (1 - std::exp(-1.0f)), 1e-5f);
    EXPECT_NEAR(angle_degrees(vec(out.direction), {0, 0, 1}), 90.0f * (1 - std::exp(-1.0f)), 1e-2f);
    smoother.update(b, 0.0f, out);
    EXPECT_NEAR(out.ambient, 0.2f + 0.8f * (1 - std::exp(-1.0f)), 1e-5f) << "dt 0 holds";
    for (int i = 0; i < 100; ++i) smoother.update(b, 0.05f, out);
    EXPECT_NEAR(out.ambient, 1.0f, 1e-4f);
    EXPECT_NEAR(out.direction[0], 1.0f, 1e-4f);
    // Opposite directions still turn, through a perpendicular.
    const glm::vec3 half = slerp_unit({0, 0, 1}, {0, 0, -1}, 0.5f);
    EXPECT_NEAR(half.z, 0.0f, 1e-5f);
    EXPECT_NEAR(glm::length(half), 1.0f, 1e-5f);
}

TEST(RenderLightSampler, SamplingAllocatesNothing) {
    RealMap map("maps/lqdm4_a6.bsp");
    // With the baked ambient cube field and the light list smoothed, as the engine samples.
    const std::vector<glm::vec3> reflectivity = texture_reflectivity(map.data->bsp(), {});
    const AmbientCubeField field =
        AmbientCubeField::bake(map.data->bsp(), map.data->lighting_rgb(), reflectivity);
    const LightSampler sampler(map.data->bsp(), map.data->lighting_rgb(), map.lights, &field);
    const auto styles = normal_lightstyles();
    const std::vector<glm::vec3> points = map.entity_origins();
    ASSERT_FALSE(points.empty());
    nqr_dlight dlight{sizeof(nqr_dlight), {0, 0, 0}, 200, {1, 1, 1}};
    EntityLighting light;
    LightContributions strongest;
    LightSmoother smoother;
    LightListSmoother list;
    size_t with_lights = 0;
    const long before = ::nq::test::g_allocations.load();
    for (const glm::vec3& p : points) {
        sampler.sample({p}, styles, {&dlight, 1}, light, &strongest);
        smoother.update(light, 0.01f, light);
        list.update(strongest, 0.01f, light);
        with_lights += light.num_lights > 0;
    }
    EXPECT_EQ(::nq::test::g_allocations.load(), before);
    EXPECT_GT(with_lights, 0u);
}

}  // namespace
}  // namespace nq
