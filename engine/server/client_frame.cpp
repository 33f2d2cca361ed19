#include "server/client_frame.h"

#include <algorithm>
#include <cmath>

#include "server/message_writer.h"

namespace nq::server {

namespace {

using namespace protocol;
using vm::Vec3f;

bool fitz(const ServerLevel& level) {
    return has_fitz_extensions(level.protocol.protocol);
}

int to_int(float v, int lo, int hi) {
    return std::isfinite(v) ? std::clamp(int(v), lo, hi) : 0;
}

// ENTALPHA: 0 means "default" (opaque), 1..255 map 0..1.
int encoded_alpha(const ServerLevel& level, uint32_t e) {
    if (!level.layout.field_alpha) return 0;
    const float a = level.vm->field_float(e, level.layout.field_alpha);
    if (a == 0 || !std::isfinite(a)) return 0;
    return std::clamp(int(std::lround(a * 254.0f + 1)), 1, 255);
}

Baseline current_state(const ServerLevel& level, uint32_t e) {
    const vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    Baseline b;
    b.origin = vm.field_vector(e, f.origin);
    b.angles = vm.field_vector(e, f.angles);
    b.model = to_int(vm.field_float(e, f.modelindex), 0, 65535);
    b.frame = to_int(vm.field_float(e, f.frame), 0, 65535);
    b.colormap = to_int(vm.field_float(e, f.colormap), 0, 255);
    b.skin = to_int(vm.field_float(e, f.skin), 0, 255);
    b.alpha = encoded_alpha(level, e);
    return b;
}

}  // namespace

void write_baselines(ServerLevel& level) {
    const vm::Vm& vm = *level.vm;
    level.baselines.assign(vm.max_edicts(), Baseline{});
    MessageWriter w(level.signon, level.protocol);
    for (uint32_t e = 0; e < vm.num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        if (!level.is_client(e) && vm.field_float(e, level.layout.fields.modelindex) == 0) continue;
        Baseline b = current_state(level, e);
        if (level.is_client(e)) {
            b.colormap = int(e);
            b.model = level.model_index("progs/player.mdl") > 0
                          ? level.model_index("progs/player.mdl")
                          : 0;
        }
        int bits = 0;
        if (fitz(level)) {
            if (b.model & 0xff00) bits |= B_LARGEMODEL;
            if (b.frame & 0xff00) bits |= B_LARGEFRAME;
            if (b.alpha) bits |= B_ALPHA;
        } else {
            b.model &= 0xff;
            b.frame &= 0xff;
            b.alpha = 0;
        }
        level.baselines[e] = b;
        if (bits) {
            w.byte(svc_spawnbaseline2);
            w.shrt(int(e));
            w.byte(bits);
        } else {
            w.byte(svc_spawnbaseline);
            w.shrt(int(e));
        }
        if (bits & B_LARGEMODEL)
            w.shrt(b.model);
        else
            w.byte(b.model);
        if (bits & B_LARGEFRAME)
            w.shrt(b.frame);
        else
            w.byte(b.frame);
        w.byte(b.colormap);
        w.byte(b.skin);
        for (int i = 0; i < 3; ++i) {
            w.coord(b.origin[size_t(i)]);
            w.angle(b.angles[size_t(i)]);
        }
        if (bits & B_ALPHA) w.byte(b.alpha);
    }
}

void write_client_data(ServerLevel& level, uint32_t player, std::vector<uint8_t>& out,
                       bool consume) {
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    MessageWriter w(out, level.protocol);

    const float dmg_take = vm.field_float(player, f.dmg_take);
    const float dmg_save = vm.field_float(player, f.dmg_save);
    if (consume && (dmg_take != 0 || dmg_save != 0)) {
        const std::optional<uint32_t> from =
            vm.edict_of(uint32_t(vm.field_int(player, f.dmg_inflictor)));
        const uint32_t other = from.value_or(0);
        const Vec3f mins = vm.field_vector(other, f.mins), maxs = vm.field_vector(other, f.maxs);
        const Vec3f origin = vm.field_vector(other, f.origin);
        w.byte(svc_damage);
        w.byte(to_int(dmg_save, 0, 255));
        w.byte(to_int(dmg_take, 0, 255));
        for (int i = 0; i < 3; ++i)
            w.coord(origin[size_t(i)] + 0.5f * (mins[size_t(i)] + maxs[size_t(i)]));
        vm.set_field_float(player, f.dmg_take, 0);
        vm.set_field_float(player, f.dmg_save, 0);
    }
    if (consume && vm.field_float(player, f.fixangle) != 0) {
        w.byte(svc_setangle);
        w.angles(vm.field_vector(player, f.angles));
        vm.set_field_float(player, f.fixangle, 0);
    }

    const Vec3f view_ofs = vm.field_vector(player, f.view_ofs);
    const Vec3f punch = vm.field_vector(player, f.punchangle);
    const Vec3f velocity = vm.field_vector(player, f.velocity);
    const float idealpitch = vm.field_float(player, f.idealpitch);
    int32_t items = int32_t(vm.field_float(player, f.items));
    if (level.layout.field_items2) {
        items |= int32_t(vm.field_float(player, level.layout.field_items2)) << 23;
    } else {
        items |= int32_t(vm.global_float(level.layout.globals.serverflags)) << 28;
    }
    const int weaponframe = to_int(vm.field_float(player, f.weaponframe), 0, 65535);
    const int armor = to_int(vm.field_float(player, f.armorvalue), 0, 65535);
    const int weapon =
        std::max(0, level.model_index_of_string(vm.field_int(player, f.weaponmodel)));
    const int ammo = to_int(vm.field_float(player, f.currentammo), 0, 65535);
    const std::array<int, 4> counts = {to_int(vm.field_float(player, f.ammo_shells), 0, 65535),
                                       to_int(vm.field_float(player, f.ammo_nails), 0, 65535),
                                       to_int(vm.field_float(player, f.ammo_rockets), 0, 65535),
                                       to_int(vm.field_float(player, f.ammo_cells), 0, 65535)};
    const int alpha = encoded_alpha(level, player);

    uint32_t bits = SU_ITEMS | SU_WEAPON;
    if (view_ofs[2] != kDefaultViewHeight) bits |= SU_VIEWHEIGHT;
    if (idealpitch != 0) bits |= SU_IDEALPITCH;
    if (int(vm.field_float(player, f.flags)) & qc::kFlOnGround) bits |= SU_ONGROUND;
    if (vm.field_float(player, f.waterlevel) >= 2) bits |= SU_INWATER;
    for (int i = 0; i < 3; ++i) {
        if (to_int(punch[size_t(i)], -128, 127) != 0) bits |= SU_PUNCH1 << i;
        if (to_int(velocity[size_t(i)] / 16, -128, 127) != 0) bits |= SU_VELOCITY1 << i;
    }
    if (weaponframe) bits |= SU_WEAPONFRAME;
    if (armor) bits |= SU_ARMOR;
    if (fitz(level)) {
        if (weapon & 0xff00) bits |= SU_WEAPON2;
        if (armor & 0xff00) bits |= SU_ARMOR2;
        if (ammo & 0xff00) bits |= SU_AMMO2;
        for (int i = 0; i < 4; ++i) {
            if (counts[size_t(i)] & 0xff00) bits |= SU_SHELLS2 << i;
        }
        if (weaponframe & 0xff00) bits |= SU_WEAPONFRAME2;
        if (alpha) bits |= SU_WEAPONALPHA;
        if (bits >= (1u << 16)) bits |= SU_EXTEND1;
        if (bits >= (1u << 24)) bits |= SU_EXTEND2;
    }

    w.byte(svc_clientdata);
    w.shrt(int(bits & 0xffff));
    if (bits & SU_EXTEND1) w.byte(int((bits >> 16) & 0xff));
    if (bits & SU_EXTEND2) w.byte(int((bits >> 24) & 0xff));
    if (bits & SU_VIEWHEIGHT) w.chr(to_int(view_ofs[2], -128, 127));
    if (bits & SU_IDEALPITCH) w.chr(to_int(idealpitch, -128, 127));
    for (int i = 0; i < 3; ++i) {
        if (bits & (SU_PUNCH1 << i)) w.chr(to_int(punch[size_t(i)], -128, 127));
        if (bits & (SU_VELOCITY1 << i)) w.chr(to_int(velocity[size_t(i)] / 16, -128, 127));
    }
    w.lng(items);
    if (bits & SU_WEAPONFRAME) w.byte(weaponframe & 0xff);
    if (bits & SU_ARMOR) w.byte(armor & 0xff);
    if (bits & SU_WEAPON) w.byte(weapon & 0xff);
    w.shrt(to_int(vm.field_float(player, f.health), -32768, 32767));
    w.byte(ammo & 0xff);
    for (int c : counts) w.byte(c & 0xff);
    w.byte(to_int(vm.field_float(player, f.weapon), 0, 255));
    if (bits & SU_WEAPON2) w.byte(weapon >> 8);
    if (bits & SU_ARMOR2) w.byte(armor >> 8);
    if (bits & SU_AMMO2) w.byte(ammo >> 8);
    for (int i = 0; i < 4; ++i) {
        if (bits & (SU_SHELLS2 << i)) w.byte(counts[size_t(i)] >> 8);
    }
    if (bits & SU_WEAPONFRAME2) w.byte(weaponframe >> 8);
    if (bits & SU_WEAPONALPHA) w.byte(alpha);
}

void write_entities(ServerLevel& level, uint32_t player, std::vector<uint8_t>& out) {
    vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    const Vec3f eye = [&] {
        const Vec3f o = vm.field_vector(player, f.origin), v = vm.field_vector(player, f.view_ofs);
        return Vec3f{o[0] + v[0], o[1] + v[1], o[2] + v[2]};
    }();
    const std::span<const uint8_t> pvs = level.pvs_of(eye);
    MessageWriter w(out, level.protocol);
    for (uint32_t e = 1; e < vm.num_edicts(); ++e) {
        if (level.edicts.is_free(e)) continue;
        if (e != player) {
            if (vm.field_float(e, f.modelindex) == 0 ||
                vm.string_or_empty(vm.field_int(e, f.model)).empty())
                continue;
            if (!pvs.empty() && level.world.leafs_complete(e)) {
                const std::span<const int32_t> leafs = level.world.leafs_of(e);
                const bool seen = std::any_of(leafs.begin(), leafs.end(), [&](int32_t leaf) {
                    return leaf > 0 && pvs_contains(pvs, uint32_t(leaf));
                });
                if (!seen) continue;
            }
        }
        const Baseline& base = level.baselines[e];
        const Baseline now = current_state(level, e);
        if (!fitz(level) && (now.model > 255 || now.frame > 255)) continue;
        uint32_t bits = 0;
        for (int i = 0; i < 3; ++i) {
            const float miss = now.origin[size_t(i)] - base.origin[size_t(i)];
            if (miss < -0.1f || miss > 0.1f) bits |= U_ORIGIN1 << i;
        }
        if (now.angles[0] != base.angles[0]) bits |= U_ANGLE1;
        if (now.angles[1] != base.angles[1]) bits |= U_ANGLE2;
        if (now.angles[2] != base.angles[2]) bits |= U_ANGLE3;
        if (int(vm.field_float(e, f.movetype)) == qc::kMoveStep) bits |= U_NOLERP;
        if (base.colormap != now.colormap) bits |= U_COLORMAP;
        if (base.skin != now.skin) bits |= U_SKIN;
        if (base.frame != now.frame) bits |= U_FRAME;
        const int effects = to_int(vm.field_float(e, f.effects), 0, 255);
        if (effects) bits |= U_EFFECTS;
        if (base.model != now.model) bits |= U_MODEL;
        if (fitz(level)) {
            if (base.alpha != now.alpha) bits |= U_ALPHA;
            if (bits & U_FRAME && now.frame & 0xff00) bits |= U_FRAME2;
            if (bits & U_MODEL && now.model & 0xff00) bits |= U_MODEL2;
        }
        if (e >= 256) bits |= U_LONGENTITY;
        if (bits >= 256) bits |= U_MOREBITS;
        if (fitz(level)) {
            if (bits >= (1u << 16)) bits |= U_EXTEND1;
            if (bits >= (1u << 24)) bits |= U_EXTEND2;
        }
        w.byte(int((bits | U_SIGNAL) & 0xff));
        if (bits & U_MOREBITS) w.byte(int((bits >> 8) & 0xff));
        if (bits & U_EXTEND1) w.byte(int((bits >> 16) & 0xff));
        if (bits & U_EXTEND2) w.byte(int((bits >> 24) & 0xff));
        if (bits & U_LONGENTITY)
            w.shrt(int(e));
        else
            w.byte(int(e));
        if (bits & U_MODEL) w.byte(now.model & 0xff);
        if (bits & U_FRAME) w.byte(now.frame & 0xff);
        if (bits & U_COLORMAP) w.byte(now.colormap);
        if (bits & U_SKIN) w.byte(now.skin);
        if (bits & U_EFFECTS) w.byte(effects);
        for (int i = 0; i < 3; ++i) {
            if (bits & (U_ORIGIN1 << i)) w.coord(now.origin[size_t(i)]);
            const uint32_t angle_bit = i == 0 ? U_ANGLE1 : i == 1 ? U_ANGLE2 : U_ANGLE3;
            if (bits & angle_bit) w.angle(now.angles[size_t(i)]);
        }
        if (bits & U_ALPHA) w.byte(now.alpha);
        if (bits & U_FRAME2) w.byte(now.frame >> 8);
        if (bits & U_MODEL2) w.byte(now.model >> 8);
    }
}

}  // namespace nq::server
