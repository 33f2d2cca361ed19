// Quake's particle effects, spawned into a ParticleSystem: explosions, blob (tarbaby)
// explosions, coloured explosions, run effects (svc_particle, spikes, gunshots), lava and
// teleport splashes, model trails, and the bright field around EF_BRIGHTFIELD entities.
// Counts, colours, spreads and lifetimes are the documented facts of Quake's effects.
#pragma once

#include <array>
#include <cstdint>

#include "client/client_random.h"
#include "client/particle_system.h"

namespace nq {

// Trail types selected by MDL flags (the numbering is Quake's).
enum class TrailKind : uint8_t {
    Rocket = 0,       // kEfRocket: fire
    Smoke = 1,        // kEfGrenade
    Blood = 2,        // kEfGib
    Tracer = 3,       // kEfTracer: green (wizard spit)
    SlightBlood = 4,  // kEfZomGib
    Tracer2 = 5,      // kEfTracer2: orange (hell knight)
    Voor = 6,         // kEfTracer3: purple (vore ball)
};

inline constexpr int kExplosionParticles = 1024;
inline constexpr int kRunEffectExplosionCount = 1024;  // svc_particle count 255 means this
inline constexpr int kFieldNormals = 162;              // directions of the bright field
inline constexpr size_t kMaxTrailParticles = 4096;     // one trail never takes more

class ParticleEffects {
  public:
    ParticleEffects(ParticleSystem& particles, ClientRandom& random);

    void explosion(double time, const Vec3& origin);
    void explosion2(double time, const Vec3& origin, int color_start, int color_length);
    void blob_explosion(double time, const Vec3& origin);
    // count particles of `color` around origin moving along direction * 15; a count of 1024
    // is a rocket explosion.
    void run_effect(double time, const Vec3& origin, const Vec3& direction, int color, int count);
    void lava_splash(double time, const Vec3& origin);
    void teleport_splash(double time, const Vec3& origin);
    // Particles along start -> end, one every 3 units (the slight-blood trail every 6), at
    // most kMaxTrailParticles.
    void trail(double time, const Vec3& start, const Vec3& end, TrailKind kind);
    void bright_field(double time, const Vec3& origin);

  private:
    Particle* spawn(double die, uint8_t color, ParticleKind kind);
    Vec3 jitter(const Vec3& origin, int spread);  // origin + (rand % (2 spread)) - spread
    Vec3 random_velocity(int spread);             // each axis (rand % (2 spread)) - spread
    bool explosion_particle(double time, const Vec3& origin, int index);  // false when full
    bool trail_particle(double time, const Vec3& at, const Vec3& direction, TrailKind kind);

    ParticleSystem& particles_;
    ClientRandom& random_;
    int tracer_count_ = 0;
    std::array<Vec3, kFieldNormals> field_normals_{};
    std::array<Vec3, kFieldNormals> field_speeds_{};
};

}  // namespace nq
