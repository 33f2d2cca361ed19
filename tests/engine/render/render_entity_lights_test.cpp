// The per-entity light list (ABI 1.4): in the synthetic box room a light entity near an entity
// is listed with the colour its linear falloff gives (brightness - distance * wait, style and
// _color applied), a light behind the ceiling is not, of six lights the four strongest are
// kept in order, dynamic lights are listed with radius - distance; the light list smoother
// fades a light that leaves the set out over several frames and one that enters in; the ABI's
// 1.4 layout appends to the 1.3 one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "formats/entities.h"
#include "render/entity_lights.h"
#include "render/light_list_smoother.h"
#include "render/light_sampler.h"
#include "render/light_smoother.h"
#include "support/render_test_support.h"
#include "support/synth_bsp.h"

namespace nq {
namespace {

using render_test::normal_lightstyles;

glm::vec3 vec(const float v[3]) {
    return {v[0], v[1], v[2]};
}

struct Room {
    std::shared_ptr<const BrushModelData> data;
    Room() {
        auto bsp = parse_bsp(test::write_bsp(test::make_box_room(), BspFormat::bsp29), "box.bsp");
        if (!bsp) throw std::runtime_error(bsp.error().to_string());
        data = BrushModelData::build(std::move(*bsp));
    }
    EntityLighting sample(const std::vector<LightEntity>& lights, const glm::vec3& p,
                          const std::vector<float>& styles = normal_lightstyles(),
                          DlightList dlights = {}) const {
        LightSampler sampler(data->bsp(), data->lighting_rgb(), lights);
        EntityLighting out;
        sampler.sample({p}, styles, dlights, out);
        return out;
    }
};

LightEntity light_at(const glm::vec3& origin, float brightness,
                     const glm::vec3& color = glm::vec3(1)) {
    LightEntity l;
    l.origin = origin;
    l.brightness = brightness;
    l.color = color;
    return l;
}

TEST(RenderEntityLights, NearbyLightIsListedWithItsLinearFalloffColour) {
    const Room room;
    const glm::vec3 p(0, 0, 20);
    std::vector<LightEntity> lights = {light_at({0, 0, 100}, 300, {1, 0.5f, 0.25f})};
    EntityLighting out = room.sample(lights, p);
    ASSERT_EQ(out.num_lights, 1u);
    const nqr_light_source& s = out.lights[0];
    EXPECT_EQ(s.size, sizeof(nqr_light_source));
    EXPECT_EQ(vec(s.position), glm::vec3(0, 0, 100));
    const float level = 300.0f - 80.0f;  // brightness - distance
    EXPECT_NEAR(s.color[0], level / 128, 1e-4f);
    EXPECT_NEAR(s.color[1], 0.5f * level / 128, 1e-4f);
    EXPECT_NEAR(s.color[2], 0.25f * level / 128, 1e-4f);
    for (uint32_t i = 1; i < NQR_MAX_ENTITY_LIGHTS; ++i) {
        EXPECT_EQ(out.lights[i].size, sizeof(nqr_light_source));
        EXPECT_EQ(vec(out.lights[i].color), glm::vec3(0));
    }

    // "wait" 2 halves the reach; the light's style scales it.
    lights[0].wait = 2;
    lights[0].style = 3;
    std::vector<float> styles = normal_lightstyles();
    styles[3] = 0.5f;
    out = room.sample(lights, p, styles);
    ASSERT_EQ(out.num_lights, 1u);
    EXPECT_NEAR(out.lights[0].color[0], 0.5f * (300.0f - 2 * 80.0f) / 128, 1e-4f);
    // Beyond its reach it brings nothing and is not listed.
    out = room.sample({light_at({0, 0, 100}, 70)}, p);
    EXPECT_EQ(out.num_lights, 0u);
}

TEST(RenderEntityLights, FarReachingFalloffsFollowTheLightTools) {
    LightEntity l = light_at({0, 0, 0}, 200);
    l.wait = 1;
    l.delay = 1;  // 1/x in units of 128
    EXPECT_FLOAT_EQ(light_level(l, 256), 100.0f);
    EXPECT_FLOAT_EQ(light_level(l, 64), 200.0f) << "never above the brightness";
    l.delay = 2;
    EXPECT_FLOAT_EQ(light_level(l, 256), 50.0f);
    l.delay = 3;
    EXPECT_FLOAT_EQ(light_level(l, 5000), 200.0f);
    l.delay = 5;
    EXPECT_FLOAT_EQ(light_level(l, 128), 50.0f);
    l.delay = 0;
    EXPECT_FLOAT_EQ(light_level(l, 150), 50.0f);
    EXPECT_FLOAT_EQ(light_level(l, 250), 0.0f);
}

TEST(RenderEntityLights, AWallBetweenRemovesTheLight) {
    const Room room;
    const glm::vec3 p(0, 0, 20);
    // Above the ceiling (z = 128): unoccluded it would bring 600 - 380 = 220.
    const LightEntity behind = light_at({0, 0, 400}, 600);
    const LightEntity inside = light_at({60, 0, 60}, 200);
    EntityLighting out = room.sample({behind, inside}, p);
    ASSERT_EQ(out.num_lights, 1u);
    EXPECT_EQ(vec(out.lights[0].position), inside.origin);
    EXPECT_EQ(room.sample({behind}, p).num_lights, 0u);
}

TEST(RenderEntityLights, OfSixLightsTheFourStrongestAreKeptStrongestFirst) {
    const Room room;
    const glm::vec3 p(0, 0, 0);
    const std::vector<LightEntity> lights = {
        light_at({80, 0, 0}, 200),    light_at({-60, 40, 30}, 250), light_at({0, 90, -20}, 160),
        light_at({50, -70, 60}, 300), light_at({-90, -90, 0}, 180), light_at({20, 20, 90}, 120)};
    struct Expected {
        glm::vec3 origin;
        float level;
    };
    std::vector<Expected> expected;
    for (const LightEntity& l : lights) {
        expected.push_back({l.origin, std::max(l.brightness - glm::length(l.origin - p), 0.0f)});
    }
    std::sort(expected.begin(), expected.end(),
              [](const Expected& a, const Expected& b) { return a.level > b.level; });
    ASSERT_GT(expected[3].level, 0.0f);
    ASSERT_GT(expected[3].level, expected[4].level + 1);
    const EntityLighting out = room.sample(lights, p);
    ASSERT_EQ(out.num_lights, 4u);
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(vec(out.lights[i].position), expected[i].origin) << i;
        EXPECT_NEAR(out.lights[i].color[1], expected[i].level / 128, 1e-4f) << i;
    }
}

TEST(RenderEntityLights, DynamicLightsAreListedWithRadiusMinusDistance) {
    const Room room;
    const glm::vec3 p(0, 0, 0);
    nqr_dlight d{sizeof(nqr_dlight), {50, 0, 0}, 200, {2.0f, 1.0f, 0.0f}};
    const EntityLighting out =
        room.sample({light_at({0, 0, 100}, 140)}, p, normal_lightstyles(), {&d, 1});
    ASSERT_EQ(out.num_lights, 2u);
    EXPECT_EQ(vec(out.lights[0].position), glm::vec3(50, 0, 0));  // 150 against 40
    EXPECT_NEAR(out.lights[0].color[0], 150.0f / 128, 1e-4f);
    EXPECT_NEAR(out.lights[0].color[1], 75.0f / 128, 1e-4f);
    EXPECT_NEAR(out.lights[0].color[2], 0.0f, 1e-6f);
    EXPECT_NEAR(out.lights[1].color[0], 40.0f / 128, 1e-4f);
}

// The strongest-lights list hands the direction the visibilities it traced: the direction is
// exactly what it is when traced on its own.
TEST(RenderEntityLights, SharedVisibilitiesLeaveTheDirectionUnchanged) {
    const auto data = render_test::load_map("maps/lqdm4_a6.bsp");
    auto entities = parse_entities(data->bsp().entities, "entities");
    ASSERT_TRUE(entities);
    std::vector<std::string> warnings;
    const std::vector<LightEntity> lights = find_light_entities(*entities, warnings);
    const auto styles = normal_lightstyles();
    size_t shared = 0, points = 0;
    for (const Entity& e : entities->entities) {
        const auto o = find_vec3(e, "origin");
        if (!o) continue;
        const glm::vec3 p((*o)[0], (*o)[1], (*o)[2] + 8);
        VisibilityCache traced;
        strongest_lights(data->bsp(), lights, p, styles, {}, &traced);
        shared += traced.count > 0;
        ++points;
        const glm::vec3 alone = dominant_light_direction(data->bsp(), lights, p, styles, {});
        const glm::vec3 with =
            dominant_light_direction(data->bsp(), lights, p, styles, {}, &traced);
        EXPECT_EQ(alone, with) << p.x << " " << p.y << " " << p.z;
    }
    EXPECT_GT(shared * 2, points);
}

// ---- fading -------------------------------------------------------------------------------

LightContribution contribution(uint32_t key, const glm::vec3& pos, float level) {
    return {key, pos, glm::vec3(level), level};
}

LightContributions set_of(std::initializer_list<LightContribution> items) {
    LightContributions out;
    for (const LightContribution& c : items) keep_strongest(out, c);
    return out;
}

// The colour (red) the output lists for the light at `pos`, 0 when it is not listed.
float listed(const nqr_entity_light& out, const glm::vec3& pos) {
    for (uint32_t i = 0; i < out.num_lights; ++i) {
        if (vec(out.lights[i].position) == pos) return out.lights[i].color[0];
    }
    return 0.0f;
}

TEST(RenderLightListSmoother, ALightLeavingTheSetFadesOutOverSeveralFrames) {
    const glm::vec3 a(10, 0, 0), b(0, 10, 0);
    LightListSmoother smoother;
    EntityLighting out{};
    smoother.update(set_of({contribution(1, a, 2.0f), contribution(2, b, 1.0f)}), 0.016f, out);
    ASSERT_EQ(out.num_lights, 2u);
    EXPECT_FLOAT_EQ(listed(out, b), 1.0f) << "the first update passes as sampled";
    const float dt = 1.0f / 60;
    float previous = 1.0f;
    int frames = 0;
    while (listed(out, b) > 0.0f && frames < 100) {
        smoother.update(set_of({contribution(1, a, 2.0f)}), dt, out);
        const float now = listed(out, b);
        EXPECT_LE(now, previous);
        EXPECT_LE(previous - now, 0.25f) << "frame " << frames;
        previous = now;
        ++frames;
        EXPECT_FLOAT_EQ(listed(out, a), 2.0f);
    }
    EXPECT_GE(frames, int(0.5f * kLightFadeSeconds / dt)) << "not gone in one frame";
    EXPECT_LE(frames, int(kLightFadeSeconds / dt) + 2);
    EXPECT_EQ(out.num_lights, 1u);
}

TEST(RenderLightListSmoother, ALightEnteringFadesInAndOrderIsByFadedStrength) {
    const glm::vec3 a(10, 0, 0), c(0, 0, 10);
    LightListSmoother smoother;
    EntityLighting out{};
    smoother.update(set_of({contribution(1, a, 1.0f)}), 0.016f, out);
    const float dt = 1.0f / 60;
    float previous = 0.0f;
    for (int frame = 0; frame < 30; ++frame) {
        smoother.update(set_of({contribution(1, a, 1.0f), contribution(7, c, 3.0f)}), dt, out);
        const float now = listed(out, c);
        EXPECT_GE(now, previous);
        EXPECT_LE(now - previous, 0.25f * 3.0f) << "frame " << frame;
        if (frame == 0) {
            EXPECT_LT(now, 0.5f);
        }
        // Strongest first, by what is shown.
        if (out.num_lights == 2) {
            EXPECT_GE(out.lights[0].color[0], out.lights[1].color[0]);
        }
        previous = now;
    }
    EXPECT_NEAR(listed(out, c), 3.0f, 1e-4f);
    EXPECT_FLOAT_EQ(out.lights[0].color[0], 3.0f);
}

TEST(RenderLightListSmoother, DynamicLightsAreFollowedByPositionAndResetRestarts) {
    LightListSmoother smoother;
    EntityLighting out{};
    // A rocket's light moves 8 units a frame and changes index: still the same light.
    smoother.update(set_of({contribution(kDynamicLightKey | 0, {0, 0, 0}, 1.0f)}), 0.016f, out);
    for (int i = 1; i < 20; ++i) {
        const glm::vec3 at(8.0f * i, 0, 0);
        smoother.update(set_of({contribution(kDynamicLightKey | uint32_t(i % 3), at, 1.0f)}),
                        1.0f / 60, out);
        ASSERT_EQ(out.num_lights, 1u) << i;
        EXPECT_FLOAT_EQ(out.lights[0].color[0], 1.0f) << i;
        EXPECT_EQ(vec(out.lights[0].position), at);
    }
    smoother.reset();
    smoother.update(set_of({contribution(3, {1, 2, 3}, 0.5f)}), 0.016f, out);
    ASSERT_EQ(out.num_lights, 1u);
    EXPECT_FLOAT_EQ(out.lights[0].color[0], 0.5f);
    // dt 0 holds.
    smoother.update(set_of({}), 0.0f, out);
    EXPECT_EQ(out.num_lights, 1u);
}

TEST(RenderLightSmoother, PassesTheLightListThrough) {
    EntityLighting a{}, b{};
    b.num_lights = 1;
    b.sources[0].size = sizeof(nqr_light_source);
    b.sources[0].color[0] = 0.75f;
    LightSmoother smoother;
    EntityLighting out{};
    smoother.update(a, 0.016f, out);
    smoother.update(b, 0.016f, out);
    EXPECT_EQ(out.num_lights, 1u);
    EXPECT_EQ(out.lights[0].color[0], 0.75f);
}

// ---- ABI ----------------------------------------------------------------------------------

// ABI 2.0: the light list is reached through a pointer, and the engine's EntityLighting keeps
// it pointing at its own sources through every copy (the smoothers copy lights around).
TEST(RenderEntityLights, EveryCopyOfALightPointsAtItsOwnList) {
    EntityLighting a;
    a.num_lights = 2;
    a.sources[1].position[0] = 42.0f;
    EXPECT_EQ(a.size, sizeof(nqr_entity_light));
    EXPECT_EQ(a.lights, a.sources.data());
    const EntityLighting b = a;
    EXPECT_EQ(b.lights, b.sources.data());
    EXPECT_EQ(b.lights[1].position[0], 42.0f);
    EntityLighting c;
    c = b;
    EXPECT_EQ(c.lights, c.sources.data());
    EXPECT_EQ(c.num_lights, 2u);
    const nqr_entity_light& abi = c;  // what a frame hands a plugin
    EXPECT_EQ(abi.lights[1].position[0], 42.0f);
}

}  // namespace
}  // namespace nq
