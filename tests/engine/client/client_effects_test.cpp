// Effects: light styles, the particle system (capacity, physics, determinism), temp entities
// (explosions, splashes, beams), dynamic lights, model trails and entity effects.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "client/client_math.h"
#include "client/particle_effects.h"
#include "client/visible_entities.h"
#include "client_test_fixture.h"

namespace nq {
namespace {

using namespace protocol;

// ---- light styles ----------------------------------------------------------------------------

TEST(LightStyles, LettersStepEveryTenthOfASecond) {
    LightStyles styles;
    ASSERT_TRUE(styles.set(0, "az"));
    EXPECT_EQ(styles.value(0, 0.0), 0.0f);                 // 'a': dark
    EXPECT_FLOAT_EQ(styles.value(0, 0.1), 25.0f / 12.0f);  // 'z'
    EXPECT_EQ(styles.value(0, 0.2), 0.0f);                 // the pattern repeats
    EXPECT_FLOAT_EQ(styles.value(0, 0.35), 25.0f / 12.0f);
    ASSERT_TRUE(styles.set(1, "m"));
    EXPECT_EQ(styles.value(1, 7.3), 1.0f);  // 'm' is normal brightness
    EXPECT_EQ(styles.value(2, 1.0), 1.0f);  // never set: normal
    EXPECT_FALSE(styles.set(64, "a"));
    EXPECT_FALSE(styles.set(-1, "a"));
    ASSERT_TRUE(styles.set(3, "abc"));
    EXPECT_FLOAT_EQ(styles.value(3, 0.3), 0.0f);  // 0.3 * 10 is letter 3, i.e. 'a' again
}

TEST(LightStyles, ClientEvaluatesThemEachFrame) {
    ClientState client;
    svc::LightStyle style;
    style.style = 5;
    style.pattern = "az";
    test::apply_all(client, {test::server_info({"maps/x.bsp"}), style});
    test::apply_all(client, {svc::Time{0.1f}});
    client.set_time(0.1);
    client.prepare_frame(LerpMode::Snap);
    EXPECT_FLOAT_EQ(client.light_style_values()[5], 25.0f / 12.0f);
    EXPECT_EQ(client.light_style_values()[0], 1.0f);
    svc::LightStyle bad;
    bad.style = 64;
    EXPECT_TRUE(client.apply(bad).has_value());
}

// ---- the particle system -------------------------------------------------------------------

TEST(Particles, CapacityIsNeverExceeded) {
    ParticleSystem particles(100);
    ClientRandom random(7);
    ParticleEffects effects(particles, random);
    effects.explosion(0, {0, 0, 0});
    EXPECT_EQ(particles.size(), 100u);
    EXPECT_EQ(particles.dropped(), 1u);  // the explosion stops at the first refusal
    EXPECT_EQ(particles.capacity(), 100u);
    particles.update(6.0, 0.1f, 800);  // explosion particles live 5 s at most
    EXPECT_EQ(particles.size(), 0u);
}

TEST(Particles, ExplosionSpreadAndRamp) {
    ParticleSystem particles;
    ClientRandom random(3);
    ParticleEffects effects(particles, random);
    const Vec3 at{100, 200, 300};
    effects.explosion(10.0, at);
    ASSERT_EQ(particles.size(), static_cast<size_t>(kExplosionParticles));
    for (const Particle& p : particles.particles()) {
        for (int i = 0; i < 3; ++i) {
            EXPECT_GE(p.origin[i], at[i] - 16);
            EXPECT_LT(p.origin[i], at[i] + 16);
            EXPECT_GE(p.velocity[i], -256);
            EXPECT_LT(p.velocity[i], 256);
        }
        EXPECT_EQ(p.color, kParticleRamp1[0]);
        EXPECT_EQ(p.die, 15.0);
        EXPECT_TRUE(p.kind == ParticleKind::Explode || p.kind == ParticleKind::Explode2);
    }
    // Explode particles run their ramp at 10 steps per second: gone after 0.8 s at most.
    particles.update(10.0, 0.9f, 800);
    for (const Particle& p : particles.particles()) EXPECT_NE(p.kind, ParticleKind::Explode);
}

TEST(Particles, GravityAndMotion) {
    ParticleSystem particles(4);
    Particle* p = particles.spawn();
    p->kind = ParticleKind::Gravity;
    p->die = 100;
    p->velocity = {10, 0, 0};
    particles.update(0.5, 0.5f, 800);
    const Particle& q = particles.particles()[0];
    EXPECT_FLOAT_EQ(q.origin[0], 5.0f);
    EXPECT_FLOAT_EQ(q.velocity[2], -0.5f * 800 * 0.05f);  // sv_gravity * 0.05 per second
    Particle* s = particles.spawn();
    s->kind = ParticleKind::Static;
    s->die = 100;
    s->velocity = {0, 0, 4};
    particles.update(1.0, 0.5f, 800);
    EXPECT_FLOAT_EQ(particles.particles()[1].velocity[2], 4.0f);  // static: no fall
}

TEST(Particles, SeededClientsProduceTheSameParticles) {
    auto run = [](uint64_t seed) {
        ParticleSystem particles;
        ClientRandom random(seed);
        ParticleEffects effects(particles, random);
        effects.lava_splash(1.0, {0, 0, 0});
        effects.teleport_splash(1.0, {64, 0, 0});
        return std::vector<Particle>(particles.particles().begin(), particles.particles().end());
    };
    auto a = run(42), b = run(42), c = run(43);
    ASSERT_EQ(a.size(), 1024u + 8u * 8u * 14u);  // 32 x 32 lava, 8 x 8 x 14 teleport
    ASSERT_EQ(a.size(), b.size());
    bool same = true, differs = false;
    for (size_t i = 0; i < a.size(); ++i) {
        same = same && a[i].origin == b[i].origin && a[i].color == b[i].color;
        differs = differs || a[i].origin != c[i].origin;
    }
    EXPECT_TRUE(same);
    EXPECT_TRUE(differs);
    for (size_t i = 0; i < 1024; ++i) {
        EXPECT_GE(a[i].color, 224);
        EXPECT_LT(a[i].color, 232);
    }
}

TEST(Particles, TrailsLayParticlesAlongThePath) {
    ParticleSystem particles;
    ClientRandom random(1);
    ParticleEffects effects(particles, random);
    effects.trail(0, {0, 0, 0}, {30, 0, 0}, TrailKind::Rocket);
    EXPECT_EQ(particles.size(), 10u);  // one every 3 units
    for (const Particle& p : particles.particles()) {
        EXPECT_EQ(p.kind, ParticleKind::Fire);
        EXPECT_GE(p.origin[0], -3);
        EXPECT_LE(p.origin[0], 30);
    }
    particles.clear();
    effects.trail(0, {0, 0, 0}, {0, 30, 0}, TrailKind::Tracer);
    ASSERT_EQ(particles.size(), 10u);
    // Tracer pairs fly sideways from the path, alternating sides.
    EXPECT_EQ(particles.particles()[0].velocity[0], -particles.particles()[1].velocity[0]);
    EXPECT_EQ(std::fabs(particles.particles()[0].velocity[0]), 30.0f);
}

// ---- temp entities and lights through the client ---------------------------------------------

class ClientEffects : public ::testing::Test {
  protected:
    void SetUp() override { start({}); }
    void start(const ClientSettings& settings) {
        client = std::make_unique<ClientState>(settings);
        test::apply_all(*client,
                        {test::server_info({"maps/x.bsp", "progs/missile.mdl"}), svc::Time{1.0f}});
        client->set_time(1.0);
    }
    std::unique_ptr<ClientState> client;
};

TEST_F(ClientEffects, ExplosionSpawnsParticlesAndALight) {
    svc::TempEntity te;
    te.type = TE_EXPLOSION;
    te.origin = {10, 20, 30};
    test::apply_all(*client, {te});
    EXPECT_EQ(client->particles().size(), static_cast<size_t>(kExplosionParticles));
    const DynamicLight* light = nullptr;
    for (const DynamicLight& l : client->dynamic_lights().all()) {
        if (l.lit(1.0)) light = &l;
    }
    ASSERT_NE(light, nullptr);
    EXPECT_EQ(light->origin, te.origin);
    EXPECT_EQ(light->radius, 350.0f);
    EXPECT_EQ(light->die, 1.5);
    // It shrinks by 300 units per second and goes out after 0.5 s.
    test::apply_all(*client, {svc::Time{1.1f}});
    client->set_time(1.1);
    client->prepare_frame(LerpMode::Interpolate);
    EXPECT_NEAR(light->radius, 350.0f - 300.0f * 0.1f, 0.01f);
    EXPECT_EQ(client->dynamic_lights().lit_count(1.6), 0u);
    EXPECT_TRUE(client->temp_entities().empty());  // NetQuake progs send the sprite themselves
}

TEST_F(ClientEffects, OptionalClientSideExplosionSprite) {
    ClientSettings settings;
    settings.explosion_sprites = true;
    start(settings);
    svc::TempEntity te;
    te.type = TE_EXPLOSION;
    te.origin = {1, 2, 3};
    test::apply_all(*client, {te});
    client->prepare_frame(LerpMode::Snap);
    ASSERT_EQ(client->temp_entities().size(), 1u);
    const TempModelEntity& sprite = client->temp_entities()[0];
    EXPECT_EQ(client->model_names()[sprite.model], "progs/s_explod.spr");
    EXPECT_EQ(sprite.origin, te.origin);
    EXPECT_EQ(sprite.frame, 0);
    test::apply_all(*client, {svc::Time{1.25f}});
    client->prepare_frame(LerpMode::Snap);
    EXPECT_EQ(client->temp_entities()[0].frame, 2);  // 10 frames per second
    test::apply_all(*client, {svc::Time{2.0f}});
    client->prepare_frame(LerpMode::Snap);
    EXPECT_TRUE(client->temp_entities().empty());  // its 6 frames are over
}

TEST_F(ClientEffects, RunEffectsAndSplashes) {
    svc::Particle p;
    p.origin = {0, 0, 0};
    p.direction = {1, 0, 0};
    p.count = 20;
    p.color = 73;
    test::apply_all(*client, {p});
    ASSERT_EQ(client->particles().size(), 20u);
    for (const Particle& q : client->particles().particles()) {
        EXPECT_EQ(q.color & ~7, 72);  // the colour's row of 8, random shade
        EXPECT_EQ(q.velocity, (Vec3{15, 0, 0}));
        EXPECT_EQ(q.kind, ParticleKind::SlowGravity);
    }
    p.count = 255;  // means a full explosion
    test::apply_all(*client, {p});
    EXPECT_EQ(client->particles().size(), 20u + 1024u);

    svc::TempEntity te;
    te.type = TE_GUNSHOT;
    test::apply_all(*client, {te});
    EXPECT_EQ(client->particles().size(), 20u + 1024u + 20u);
    te.type = TE_TAREXPLOSION;
    test::apply_all(*client, {te});
    EXPECT_EQ(client->particles().size(), 20u + 1024u + 20u + 1024u);
    te.type = TE_EXPLOSION2;
    te.color_start = 100;
    te.color_length = 8;
    size_t before = client->particles().size();
    test::apply_all(*client, {te});
    ASSERT_EQ(client->particles().size(), before + 512u);
    for (size_t i = before; i < client->particles().size(); ++i) {
        uint8_t c = client->particles().particles()[i].color;
        EXPECT_GE(c, 100);
        EXPECT_LT(c, 108);
    }
}

TEST_F(ClientEffects, BeamsAreRepeatedBoltModels) {
    svc::TempEntity te;
    te.type = TE_LIGHTNING1;
    te.entity = 9;
    te.origin = {0, 0, 0};
    te.end = {100, 0, 0};
    test::apply_all(*client, {te});
    client->prepare_frame(LerpMode::Snap);
    auto segments = client->temp_entities();
    ASSERT_EQ(segments.size(), 4u);  // at 0, 30, 60, 90
    for (size_t i = 0; i < segments.size(); ++i) {
        EXPECT_EQ(client->model_names()[segments[i].model], "progs/bolt.mdl");
        EXPECT_EQ(segments[i].origin, (Vec3{30.0f * i, 0, 0}));
        EXPECT_EQ(segments[i].angles[0], 0.0f);
        EXPECT_EQ(segments[i].angles[1], 0.0f);
    }
    // The same owner's next bolt replaces it; a bolt straight up has pitch 90.
    te.type = TE_LIGHTNING2;
    te.end = {0, 0, 45};
    test::apply_all(*client, {te});
    client->prepare_frame(LerpMode::Snap);
    segments = client->temp_entities();
    ASSERT_EQ(segments.size(), 2u);
    EXPECT_EQ(client->model_names()[segments[0].model], "progs/bolt2.mdl");
    EXPECT_EQ(segments[0].angles[0], 90.0f);
    EXPECT_EQ(beam_angles({0, -1, 0})[1], 270.0f);
    // A beam lasts 0.2 s after its last message.
    test::apply_all(*client, {svc::Time{1.25f}});
    client->prepare_frame(LerpMode::Snap);
    EXPECT_TRUE(client->temp_entities().empty());
}

TEST_F(ClientEffects, RocketsLeaveTrailsAndLight) {
    std::vector<ModelInfo> info(client->model_names().size());
    info[2] = test::alias_info(1, {}, kEfRocket);
    client->set_model_info(info);
    test::apply_all(*client, {test::baseline(8, 2, {0, 0, 0}), test::origin_update(8, {0, 0, 0})});
    client->prepare_frame(LerpMode::Snap);
    const size_t before = client->particles().size();
    test::apply_all(*client, {svc::Time{1.1f}, test::origin_update(8, {60, 0, 0})});
    client->set_time(1.1);
    client->prepare_frame(LerpMode::Snap);
    EXPECT_EQ(client->particles().size() - before, 20u);  // 60 units, one every 3
    bool light = false;
    for (const DynamicLight& l : client->dynamic_lights().all()) {
        if (l.key == 8 && l.lit(client->time()) && l.radius == 200) light = true;
    }
    EXPECT_TRUE(light);
}

TEST_F(ClientEffects, MuzzleFlashAndGlowLights) {
    svc::EntityUpdate u = test::origin_update(3, {0, 0, 0});
    u.bits |= U_MODEL | U_EFFECTS;
    u.model = 2;
    u.effects = kEffectMuzzleFlash;
    test::apply_all(*client, {u});
    client->prepare_frame(LerpMode::Snap);
    const DynamicLight* flash = nullptr;
    for (const DynamicLight& l : client->dynamic_lights().all()) {
        if (l.key == 3) flash = &l;
    }
    ASSERT_NE(flash, nullptr);
    EXPECT_EQ(flash->origin, (Vec3{18, 0, 16}));  // 18 units ahead, 16 up
    EXPECT_GE(flash->radius, 200);
    EXPECT_LT(flash->radius, 232);
    EXPECT_EQ(flash->minlight, 32);
    EXPECT_NEAR(flash->die, client->time() + 0.1, 1e-9);
    EXPECT_TRUE(client->entity(3)->anim.reset_next_change);
}

}  // namespace
}  // namespace nq
