#include "client/particle_effects.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "client/client_math.h"

namespace nq {

ParticleEffects::ParticleEffects(ParticleSystem& particles, ClientRandom& random)
    : particles_(particles), random_(random) {
    // Evenly spread unit directions (a Fibonacci sphere) and a slow random spin for each.
    const float golden = std::numbers::pi_v<float> * (3.0f - std::sqrt(5.0f));
    for (int i = 0; i < kFieldNormals; ++i) {
        float z = 1.0f - 2.0f * (static_cast<float>(i) + 0.5f) / kFieldNormals;
        float r = std::sqrt(1.0f - z * z);
        float phi = golden * static_cast<float>(i);
        field_normals_[i] = {r * std::cos(phi), r * std::sin(phi), z};
        for (float& s : field_speeds_[i]) s = static_cast<float>(random_.rand15() & 255) * 0.01f;
    }
}

Particle* ParticleEffects::spawn(double die, uint8_t color, ParticleKind kind) {
    Particle* p = particles_.spawn();
    if (p) {
        p->die = die;
        p->color = color;
        p->kind = kind;
    }
    return p;
}

Vec3 ParticleEffects::jitter(const Vec3& origin, int spread) {
    Vec3 out = origin;
    for (float& v : out) v += static_cast<float>(random_.rand15() % (2 * spread) - spread);
    return out;
}

Vec3 ParticleEffects::random_velocity(int spread) {
    return jitter({0, 0, 0}, spread);
}

bool ParticleEffects::explosion_particle(double time, const Vec3& origin, int index) {
    const ParticleKind kind = (index & 1) ? ParticleKind::Explode : ParticleKind::Explode2;
    Particle* p = spawn(time + 5, kParticleRamp1[0], kind);
    if (!p) return false;
    p->ramp = static_cast<float>(random_.rand15() & 3);
    p->origin = jitter(origin, 16);
    p->velocity = random_velocity(256);
    return true;
}

void ParticleEffects::explosion(double time, const Vec3& origin) {
    for (int i = 0; i < kExplosionParticles; ++i) {
        if (!explosion_particle(time, origin, i)) return;  // full: the rest would fail too
    }
}

void ParticleEffects::explosion2(double time, const Vec3& origin, int color_start,
                                 int color_length) {
    for (int i = 0; i < 512; ++i) {
        int offset = color_length > 0 ? i % color_length : 0;
        Particle* p =
            spawn(time + 0.3, static_cast<uint8_t>(color_start + offset), ParticleKind::Blob);
        if (!p) return;
        p->origin = jitter(origin, 16);
        p->velocity = random_velocity(256);
    }
}

void ParticleEffects::blob_explosion(double time, const Vec3& origin) {
    for (int i = 0; i < kExplosionParticles; ++i) {
        double die = time + 1 + (random_.rand15() & 8) * 0.05;
        bool odd = (i & 1) != 0;
        int color = (odd ? 66 : 150) + random_.rand15() % 6;
        Particle* p =
            spawn(die, static_cast<uint8_t>(color), odd ? ParticleKind::Blob : ParticleKind::Blob2);
        if (!p) return;
        p->origin = jitter(origin, 16);
        p->velocity = random_velocity(256);
    }
}

void ParticleEffects::run_effect(double time, const Vec3& origin, const Vec3& direction, int color,
                                 int count) {
    for (int i = 0; i < count; ++i) {
        if (count == kRunEffectExplosionCount) {
            if (!explosion_particle(time, origin, i)) return;
            continue;
        }
        double die = time + 0.1 * (random_.rand15() % 5);
        int shade = (color & ~7) + (random_.rand15() & 7);
        Particle* p = spawn(die, static_cast<uint8_t>(shade), ParticleKind::SlowGravity);
        if (!p) return;
        for (int j = 0; j < 3; ++j) {
            p->origin[j] = origin[j] + static_cast<float>((random_.rand15() & 15) - 8);
        }
        p->velocity = vscale(direction, 15);
    }
}

void ParticleEffects::lava_splash(double time, const Vec3& origin) {
    for (int i = -16; i < 16; ++i) {
        for (int j = -16; j < 16; ++j) {
            double die = time + 2 + (random_.rand15() & 31) * 0.02;
            int color = 224 + (random_.rand15() & 7);
            Particle* p = spawn(die, static_cast<uint8_t>(color), ParticleKind::SlowGravity);
            if (!p) return;
            Vec3 dir = {static_cast<float>(j * 8 + (random_.rand15() & 7)),
                        static_cast<float>(i * 8 + (random_.rand15() & 7)), 256};
            p->origin = {origin[0] + dir[0], origin[1] + dir[1],
                         origin[2] + static_cast<float>(random_.rand15() & 63)};
            normalize(dir);
            p->velocity = vscale(dir, static_cast<float>(50 + (random_.rand15() & 63)));
        }
    }
}

void ParticleEffects::teleport_splash(double time, const Vec3& origin) {
    for (int i = -16; i < 16; i += 4) {
        for (int j = -16; j < 16; j += 4) {
            for (int k = -24; k < 32; k += 4) {
                double die = time + 0.2 + (random_.rand15() & 7) * 0.02;
                int color = 7 + (random_.rand15() & 7);
                Particle* p = spawn(die, static_cast<uint8_t>(color), ParticleKind::SlowGravity);
                if (!p) return;
                Vec3 dir = {static_cast<float>(j * 8), static_cast<float>(i * 8),
                            static_cast<float>(k * 8)};
                p->origin = {origin[0] + static_cast<float>(i + (random_.rand15() & 3)),
                             origin[1] + static_cast<float>(j + (random_.rand15() & 3)),
                             origin[2] + static_cast<float>(k + (random_.rand15() & 3))};
                normalize(dir);
                p->velocity = vscale(dir, static_cast<float>(50 + (random_.rand15() & 63)));
            }
        }
    }
}

bool ParticleEffects::trail_particle(double time, const Vec3& at, const Vec3& direction,
                                     TrailKind kind) {
    auto blood = [&] { return static_cast<uint8_t>(67 + (random_.rand15() & 3)); };
    Particle* p = nullptr;
    switch (kind) {
        case TrailKind::Rocket:
        case TrailKind::Smoke: {
            int ramp = (random_.rand15() & 3) + (kind == TrailKind::Smoke ? 2 : 0);
            p = spawn(time + 2, kParticleRamp3[ramp], ParticleKind::Fire);
            if (p) p->ramp = static_cast<float>(ramp);
            break;
        }
        case TrailKind::Blood:
        case TrailKind::SlightBlood:
            p = spawn(time + 2, blood(), ParticleKind::Gravity);
            break;
        case TrailKind::Tracer:
        case TrailKind::Tracer2: {
            int base = kind == TrailKind::Tracer ? 52 : 230;
            p = spawn(time + 0.5, static_cast<uint8_t>(base + ((tracer_count_ & 4) << 1)),
                      ParticleKind::Static);
            if (!p) return false;
            ++tracer_count_;
            // Alternate sides: the pair of particles spreads sideways from the path.
            float side = (tracer_count_ & 1) ? 30.0f : -30.0f;
            p->origin = at;
            p->velocity = {side * direction[1], -side * direction[0], 0};
            return true;
        }
        case TrailKind::Voor:
            p = spawn(time + 0.3, static_cast<uint8_t>(9 * 16 + 8 + (random_.rand15() & 3)),
                      ParticleKind::Static);
            if (!p) return false;
            for (int j = 0; j < 3; ++j) {
                p->origin[j] = at[j] + static_cast<float>((random_.rand15() & 15) - 8);
            }
            return true;
    }
    if (!p) return false;
    p->origin = jitter(at, 3);
    return true;
}

void ParticleEffects::trail(double time, const Vec3& start, const Vec3& end, TrailKind kind) {
    Vec3 direction = vsub(end, start);
    const float length = normalize(direction);
    if (!(length > 0)) return;
    const float spacing = kind == TrailKind::SlightBlood ? 6.0f : 3.0f;
    // Counted rather than stepped: a huge jump must not loop on float steps that stop adding.
    const double wanted = std::ceil(static_cast<double>(length) / spacing);
    const size_t count = static_cast<size_t>(std::min(wanted, double(kMaxTrailParticles)));
    for (size_t i = 0; i < count; ++i) {
        const float along = static_cast<float>(i) * spacing;
        if (!trail_particle(time, vmad(start, along, direction), direction, kind)) return;
    }
}

void ParticleEffects::bright_field(double time, const Vec3& origin) {
    constexpr float kDistance = 64, kBeamLength = 16;
    for (int i = 0; i < kFieldNormals; ++i) {
        float yaw = static_cast<float>(time) * field_speeds_[i][0];
        float pitch = static_cast<float>(time) * field_speeds_[i][1];
        Vec3 forward = {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw),
                        -std::sin(pitch)};
        Particle* p = spawn(time + 0.01, kParticleRamp1[0], ParticleKind::Explode);
        if (!p) return;
        p->origin = vmad(vmad(origin, kDistance, field_normals_[i]), kBeamLength, forward);
    }
}

}  // namespace nq
