#include "client/particle_system.h"

namespace nq {

ParticleSystem::ParticleSystem(size_t capacity) : items_(capacity) {}

Particle* ParticleSystem::spawn() {
    if (count_ == items_.size()) {
        ++dropped_;
        return nullptr;
    }
    Particle* p = &items_[count_++];
    *p = Particle{};
    return p;
}

void ParticleSystem::clear() {
    count_ = 0;
}

void ParticleSystem::step(Particle& p, float dt, float gravity) const {
    const float fall = dt * gravity * 0.05f;
    const float grow = 4.0f * dt;
    p.origin = {p.origin[0] + p.velocity[0] * dt, p.origin[1] + p.velocity[1] * dt,
                p.origin[2] + p.velocity[2] * dt};
    switch (p.kind) {
        case ParticleKind::Static:
            break;
        case ParticleKind::Fire:
            p.ramp += dt * 5.0f;
            if (p.ramp >= static_cast<float>(kParticleRamp3.size())) {
                p.die = -1;
            } else {
                p.color = kParticleRamp3[static_cast<size_t>(p.ramp)];
            }
            p.velocity[2] += fall;
            break;
        case ParticleKind::Explode:
            p.ramp += dt * 10.0f;
            if (p.ramp >= 8.0f) {
                p.die = -1;
            } else {
                p.color = kParticleRamp1[static_cast<size_t>(p.ramp)];
            }
            for (float& v : p.velocity) v += v * grow;
            p.velocity[2] -= fall;
            break;
        case ParticleKind::Explode2:
            p.ramp += dt * 15.0f;
            if (p.ramp >= 8.0f) {
                p.die = -1;
            } else {
                p.color = kParticleRamp2[static_cast<size_t>(p.ramp)];
            }
            for (float& v : p.velocity) v -= v * dt;
            p.velocity[2] -= fall;
            break;
        case ParticleKind::Blob:
            for (float& v : p.velocity) v += v * grow;
            p.velocity[2] -= fall;
            break;
        case ParticleKind::Blob2:
            p.velocity[0] -= p.velocity[0] * grow;
            p.velocity[1] -= p.velocity[1] * grow;
            p.velocity[2] -= fall;
            break;
        case ParticleKind::Gravity:
        case ParticleKind::SlowGravity:
            p.velocity[2] -= fall;
            break;
    }
}

void ParticleSystem::update(double time, float frame_time, float gravity) {
    size_t i = 0;
    while (i < count_) {
        Particle& p = items_[i];
        if (frame_time > 0) step(p, frame_time, gravity);
        if (p.die < time) {
            p = items_[--count_];  // order does not matter: swap the last one in
        } else {
            ++i;
        }
    }
}

}  // namespace nq
