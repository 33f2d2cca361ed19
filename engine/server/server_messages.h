// The server's messages that QuakeC and the physics start: sounds, particles, prints, light
// styles, static entities and sounds. Each writes Quake's wire form into the level's buffer the
// message belongs to (the frame's datagram, every client's reliable stream, or the signon).
#pragma once

#include <cstdint>
#include <string_view>

#include "server/server_level.h"

namespace nq::server {

// svc_sound into the datagram; a sample not precached is a warning and no sound.
void write_sound(ServerLevel& level, uint32_t edict, int channel, std::string_view sample,
                 float volume, float attenuation);
// svc_particle into the datagram.
void write_particle(ServerLevel& level, const vm::Vec3f& origin, const vm::Vec3f& direction,
                    int color, int count);
// svc_print / svc_centerprint / svc_stufftext to the local client's reliable stream.
void write_client_text(ServerLevel& level, int svc, std::string_view text);
// svc_lightstyle to every client, and kept for clients that connect later.
void set_lightstyle(ServerLevel& level, int style, std::string_view pattern);
// svc_spawnstatic(2) of the entity into the signon.
void write_static_entity(ServerLevel& level, uint32_t edict);
// svc_spawnstaticsound(2) into the signon.
void write_static_sound(ServerLevel& level, const vm::Vec3f& origin, std::string_view sample,
                        float volume, float attenuation);

// The sound sink the physics uses (water splashes): write_sound on this level.
class LevelSoundSink final : public SoundSink {
  public:
    explicit LevelSoundSink(ServerLevel& level) : level_(level) {}
    void start_sound(uint32_t edict, int channel, std::string_view sample, float volume,
                     float attenuation) override {
        write_sound(level_, edict, channel, sample, volume, attenuation);
    }

  private:
    ServerLevel& level_;
};

}  // namespace nq::server
