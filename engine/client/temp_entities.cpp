// Temporary effects sent by the server: svc_temp_entity (impacts, explosions, splashes, beams)
// and svc_particle. Sounds they would make are the engine's business.
#include <string>

#include "client/client_state.h"

namespace nq {
namespace {

using namespace protocol;

constexpr Vec3 kNoDirection{0, 0, 0};

}  // namespace

void ClientState::spawn_explosion_sprite(const Vec3& origin) {
    ExplosionSprite* slot = &explosions_[0];
    for (ExplosionSprite& e : explosions_) {
        if (e.start < 0) {
            slot = &e;
            break;
        }
        if (e.start < slot->start) slot = &e;  // all busy: replace the oldest
    }
    *slot = {origin, time_};
}

std::optional<std::string> ClientState::on_temp_entity(const svc::TempEntity& m) {
    auto explosion_light = [&] {
        DynamicLight& light = dlights_.allocate(0, time_);
        light.origin = m.origin;
        light.radius = 350;
        light.die = time_ + 0.5;
        light.decay = 300;
    };
    auto beam = [&](int model) {
        if (!beams_.start(m.entity, model, time_, m.origin, m.end)) warn("beam list overflow");
    };
    switch (m.type) {
        case TE_SPIKE:
            effects_.run_effect(time_, m.origin, kNoDirection, 0, 10);
            break;
        case TE_SUPERSPIKE:
        case TE_GUNSHOT:
            effects_.run_effect(time_, m.origin, kNoDirection, 0, 20);
            break;
        case TE_WIZSPIKE:
            effects_.run_effect(time_, m.origin, kNoDirection, 20, 30);
            break;
        case TE_KNIGHTSPIKE:
            effects_.run_effect(time_, m.origin, kNoDirection, 226, 20);
            break;
        case TE_EXPLOSION:
            effects_.explosion(time_, m.origin);
            explosion_light();
            if (settings_.explosion_sprites) spawn_explosion_sprite(m.origin);
            break;
        case TE_EXPLOSION2:
            effects_.explosion2(time_, m.origin, m.color_start, m.color_length);
            explosion_light();
            break;
        case TE_TAREXPLOSION:
            effects_.blob_explosion(time_, m.origin);
            break;
        case TE_LAVASPLASH:
            effects_.lava_splash(time_, m.origin);
            break;
        case TE_TELEPORT:
            effects_.teleport_splash(time_, m.origin);
            break;
        case TE_LIGHTNING1:
            beam(client_models_.bolt);
            break;
        case TE_LIGHTNING2:
            beam(client_models_.bolt2);
            break;
        case TE_LIGHTNING3:
            beam(client_models_.bolt3);
            break;
        case TE_BEAM:
            beam(client_models_.beam);
            break;
        default:
            return "svc_temp_entity: unknown type " + std::to_string(m.type);
    }
    return std::nullopt;
}

void ClientState::on_particle(const svc::Particle& m) {
    const int count = m.count == 255 ? kRunEffectExplosionCount : m.count;
    effects_.run_effect(time_, m.origin, m.direction, m.color, count);
}

}  // namespace nq
