#include "server/monster_waking.h"

#include <cmath>

namespace nq::server {

namespace {

constexpr uint32_t kPlayer = 1;
constexpr double kFrame = 1.0 / 72;

}  // namespace

std::vector<uint32_t> living_monsters(ServerLevel& level) {
    const vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    std::vector<uint32_t> out;
    for (uint32_t e = 2; e < vm.num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        if ((int(vm.field_float(e, f.flags)) & qc::kFlMonster) && vm.field_float(e, f.health) > 0) {
            out.push_back(e);
        }
    }
    return out;
}

int monsters_hunting_player(ServerLevel& level) {
    const vm::Vm& vm = *level.vm;
    int n = 0;
    for (uint32_t m : living_monsters(level)) {
        n += uint32_t(vm.field_int(m, level.layout.fields.enemy)) == vm.entity_value(kPlayer);
    }
    return n;
}

std::optional<vm::Vec3f> clear_spot_near(ServerLevel& level, uint32_t m, float distance) {
    const vm::Vec3f at = level.vm->field_vector(m, level.layout.fields.origin);
    for (int k = 0; k < 8; ++k) {
        const float r = float(k * M_PI / 4);
        const vm::Vec3f spot = {at[0] + distance * std::cos(r), at[1] + distance * std::sin(r),
                                at[2]};
        const MoveTrace t =
            level.world.move(at, {-16, -16, -24}, {16, 16, 32}, spot, MoveKind::normal, m);
        if (t.fraction == 1 && !t.start_solid) return spot;
    }
    return std::nullopt;
}

void place_player(ServerLevel& level, const vm::Vec3f& at) {
    level.vm->set_field_vector(kPlayer, level.layout.fields.origin, at);
    level.vm->set_field_vector(kPlayer, level.layout.fields.velocity, {0, 0, 0});
    level.world.link(kPlayer, false);
}

bool wake_monsters(Server& server, double share) {
    ServerLevel* level = server.level();
    if (!level) return false;
    const std::vector<uint32_t> all = living_monsters(*level);
    const int wanted = int(std::ceil(share * double(all.size())));
    for (uint32_t m : all) {
        if (monsters_hunting_player(*level) >= wanted) break;
        if (level->edicts.is_free(m)) continue;
        const std::optional<vm::Vec3f> spot = clear_spot_near(*level, m, 256);
        if (!spot) continue;
        place_player(*level, *spot);
        for (int i = 0; i < 72; ++i) {
            if (!server.frame(kFrame, {})) return false;
        }
    }
    return true;
}

}  // namespace nq::server
