#include "server/server_commands.h"

#include <cstdio>

namespace nq::server {

namespace {

constexpr uint32_t kPlayer = 1;
constexpr int kItShotgun = 1, kItArmor1 = 8192, kItArmor2 = 16384, kItArmor3 = 32768;

std::string toggle_flag(ServerLevel& level, int flag, const char* name) {
    const uint32_t field = level.layout.fields.flags;
    const int flags = int(level.vm->field_float(kPlayer, field)) ^ flag;
    level.vm->set_field_float(kPlayer, field, float(flags));
    return std::string(name) + ((flags & flag) ? " ON" : " OFF");
}

std::string toggle_movetype(ServerLevel& level, int movetype, const char* name) {
    const uint32_t field = level.layout.fields.movetype;
    const bool on = int(level.vm->field_float(kPlayer, field)) != movetype;
    level.vm->set_field_float(kPlayer, field, float(on ? movetype : qc::kMoveWalk));
    return std::string(name) + (on ? " ON" : " OFF");
}

}  // namespace

std::string toggle_god(ServerLevel& level) {
    return toggle_flag(level, qc::kFlGodMode, "godmode");
}
std::string toggle_notarget(ServerLevel& level) {
    return toggle_flag(level, qc::kFlNoTarget, "notarget");
}
std::string toggle_noclip(ServerLevel& level) {
    return toggle_movetype(level, qc::kMoveNoclip, "noclip");
}
std::string toggle_fly(ServerLevel& level) {
    return toggle_movetype(level, qc::kMoveFly, "flymode");
}

std::string give(ServerLevel& level, std::string_view what, float amount) {
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    if (what.empty()) return "usage: give <s|n|r|c|h|a|2..8> [amount]";
    const char c = what[0];
    auto set = [&](uint32_t field) { vm.set_field_float(kPlayer, field, amount); };
    switch (c) {
        case 's':
            set(f.ammo_shells);
            break;
        case 'n':
            set(f.ammo_nails);
            break;
        case 'r':
            set(f.ammo_rockets);
            break;
        case 'c':
            set(f.ammo_cells);
            break;
        case 'h':
            set(f.health);
            break;
        case 'a': {
            const int items =
                int(vm.field_float(kPlayer, f.items)) & ~(kItArmor1 | kItArmor2 | kItArmor3);
            const int bit = amount > 150 ? kItArmor3 : amount > 100 ? kItArmor2 : kItArmor1;
            const float type = amount > 150 ? 0.8f : amount > 100 ? 0.6f : 0.3f;
            vm.set_field_float(kPlayer, f.items, float(items | bit));
            vm.set_field_float(kPlayer, f.armortype, type);
            set(f.armorvalue);
            break;
        }
        default:
            if (c >= '2' && c <= '8') {
                const int items = int(vm.field_float(kPlayer, f.items)) | (kItShotgun << (c - '2'));
                vm.set_field_float(kPlayer, f.items, float(items));
                break;
            }
            return "give: unknown item " + std::string(what);
    }
    return {};
}

std::string kill_player(ServerLevel& level) {
    vm::Vm& vm = *level.vm;
    const GlobalOffsets& g = level.layout.globals;
    vm.set_global_float(g.time, float(level.game.time));
    vm.set_global_word(g.self, vm.entity_value(kPlayer));
    if (!vm.execute(int32_t(vm.global_word(g.ClientKill)))) return vm.error()->to_string();
    return {};
}

std::string set_position(ServerLevel& level, const Vec3f& origin) {
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    vm.set_field_vector(kPlayer, f.origin, origin);
    vm.set_field_vector(kPlayer, f.velocity, Vec3f{0, 0, 0});
    // Triggers are touched by the next frame's move, as after a teleport, not from the console.
    level.world.link(kPlayer, false);
    char line[96];
    std::snprintf(line, sizeof line, "setpos %.1f %.1f %.1f", double(origin[0]), double(origin[1]),
                  double(origin[2]));
    return line;
}

std::string status_text(ServerLevel& level) {
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    const GlobalOffsets& g = level.layout.globals;
    int hunting = 0;  // monsters whose enemy is the player
    for (uint32_t e = 2; e < vm.num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        if (!(int(vm.field_float(e, f.flags)) & qc::kFlMonster)) continue;
        if (vm.field_float(e, f.health) <= 0) continue;
        hunting += uint32_t(vm.field_int(e, f.enemy)) == vm.entity_value(kPlayer);
    }
    char line[320];
    std::snprintf(line, sizeof line,
                  "map: %s\ntime: %.1f\nedicts: %u of %u\nplayer: %s, health %d, frags %d\n"
                  "monsters: %d / %d killed, %d hunting the player; secrets: %d / %d",
                  level.map_name.c_str(), level.game.time, vm.num_edicts(), vm.max_edicts(),
                  level.client.name.c_str(), int(vm.field_float(kPlayer, f.health)),
                  int(vm.field_float(kPlayer, f.frags)), int(vm.global_float(g.killed_monsters)),
                  int(vm.global_float(g.total_monsters)), hunting,
                  int(vm.global_float(g.found_secrets)), int(vm.global_float(g.total_secrets)));
    return line;
}

}  // namespace nq::server
