#include "server/server_messages.h"

#include <algorithm>
#include <cmath>

#include "server/message_writer.h"

namespace nq::server {

namespace {

using namespace protocol;

bool fitz(const ServerLevel& level) {
    return has_fitz_extensions(level.protocol.protocol);
}

int to_byte(float v) {
    return std::isfinite(v) ? std::clamp(int(v), 0, 255) : 0;
}

}  // namespace

void write_sound(ServerLevel& level, uint32_t edict, int channel, std::string_view sample,
                 float volume, float attenuation) {
    const int sound = level.sound_index(sample);
    if (sound <= 0) {
        level.host.print("SV_StartSound: " + std::string(sample) + " not precached\n");
        return;
    }
    const int vol = to_byte(volume * 255);
    if (!(attenuation >= 0 && attenuation <= 4)) attenuation = 1;
    channel = std::clamp(channel, 0, 7);
    const bool large_entity = edict >= 8192, large_sound = sound >= 256;
    if (!fitz(level) && (large_entity || large_sound)) return;  // protocol 15 cannot say it
    int mask = 0;
    if (vol != kDefaultSoundVolume) mask |= SND_VOLUME;
    if (attenuation != kDefaultSoundAttenuation) mask |= SND_ATTENUATION;
    if (large_entity) mask |= SND_LARGEENTITY;
    if (large_sound) mask |= SND_LARGESOUND;

    MessageWriter w(level.datagram, level.protocol);
    w.byte(svc_sound);
    w.byte(mask);
    if (mask & SND_VOLUME) w.byte(vol);
    if (mask & SND_ATTENUATION) w.byte(int(attenuation * 64));
    if (large_entity) {
        w.shrt(int(edict));
        w.byte(channel);
    } else {
        w.shrt(int(edict << 3) | channel);
    }
    if (large_sound) {
        w.shrt(sound);
    } else {
        w.byte(sound);
    }
    // From the middle of the entity's box (a door's origin is at the map's origin).
    const vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    const vm::Vec3f origin = vm.field_vector(edict, f.origin);
    const vm::Vec3f mins = vm.field_vector(edict, f.mins), maxs = vm.field_vector(edict, f.maxs);
    for (int i = 0; i < 3; ++i) w.coord(origin[i] + 0.5f * (mins[i] + maxs[i]));
}

void write_particle(ServerLevel& level, const vm::Vec3f& origin, const vm::Vec3f& direction,
                    int color, int count) {
    MessageWriter w(level.datagram, level.protocol);
    w.byte(svc_particle);
    w.coords(origin);
    for (float d : direction) {
        const float v = std::isfinite(d) ? d * 16 : 0;
        w.chr(std::clamp(int(v), -128, 127));
    }
    w.byte(std::clamp(count, 0, 255));
    w.byte(color & 0xff);
}

void write_client_text(ServerLevel& level, int svc, std::string_view text) {
    MessageWriter w(level.client.message, level.protocol);
    w.byte(svc);
    w.string(text);
}

void set_lightstyle(ServerLevel& level, int style, std::string_view pattern) {
    if (style < 0 || style >= kMaxLightStyles) return;
    level.lightstyles[size_t(style)] = std::string(pattern.substr(0, 64));
    if (level.loading) return;  // the signon sends them all
    MessageWriter w(level.client.message, level.protocol);
    w.byte(svc_lightstyle);
    w.byte(style);
    w.string(level.lightstyles[size_t(style)]);
}

void write_static_entity(ServerLevel& level, uint32_t edict) {
    const vm::Vm& vm = *level.vm;
    const FieldOffsets& f = level.layout.fields;
    const int model = level.model_index(vm.string_or_empty(vm.field_int(edict, f.model)));
    if (model <= 0) return;  // Quake drops a static entity without a model
    const int frame = int(vm.field_float(edict, f.frame));
    int alpha = 0;
    if (level.layout.field_alpha) {
        const float a = vm.field_float(edict, level.layout.field_alpha);
        alpha = a == 0 ? 0 : std::clamp(int(std::lround(a * 254.0f + 1)), 1, 255);
    }
    int bits = 0;
    if (fitz(level)) {
        if (model & 0xff00) bits |= B_LARGEMODEL;
        if (frame & 0xff00) bits |= B_LARGEFRAME;
        if (alpha) bits |= B_ALPHA;
    } else if (model > 255 || frame > 255 || frame < 0) {
        return;
    }
    MessageWriter w(level.signon, level.protocol);
    if (bits) {
        w.byte(svc_spawnstatic2);
        w.byte(bits);
    } else {
        w.byte(svc_spawnstatic);
    }
    if (bits & B_LARGEMODEL)
        w.shrt(model);
    else
        w.byte(model);
    if (bits & B_LARGEFRAME)
        w.shrt(frame);
    else
        w.byte(frame);
    w.byte(int(vm.field_float(edict, f.colormap)));
    w.byte(int(vm.field_float(edict, f.skin)));
    const vm::Vec3f origin = vm.field_vector(edict, f.origin);
    const vm::Vec3f angles = vm.field_vector(edict, f.angles);
    for (int i = 0; i < 3; ++i) {
        w.coord(origin[i]);
        w.angle(angles[i]);
    }
    if (bits & B_ALPHA) w.byte(alpha);
}

void write_static_sound(ServerLevel& level, const vm::Vec3f& origin, std::string_view sample,
                        float volume, float attenuation) {
    const int sound = level.sound_index(sample);
    if (sound <= 0) {
        level.host.print("no precache: " + std::string(sample) + "\n");
        return;
    }
    const bool large = sound > 255;
    if (large && !fitz(level)) return;
    MessageWriter w(level.signon, level.protocol);
    w.byte(large ? svc_spawnstaticsound2 : svc_spawnstaticsound);
    w.coords(origin);
    if (large)
        w.shrt(sound);
    else
        w.byte(sound);
    w.byte(to_byte(volume * 255));
    w.byte(to_byte(attenuation * 64));
}

}  // namespace nq::server
