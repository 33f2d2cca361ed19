#include "sound/client_sound_feed.h"

#include "client/client_math.h"

namespace nq {

Listener listener_for_view(const Vec3& origin, const Vec3& angles, int view_entity) {
    const Basis basis = angle_vectors(angles);
    return Listener{origin, basis.right, view_entity};
}

void ClientSoundFeed::feed(ClientState& client, SoundSystem& sound, const Listener& listener) {
    if (!seen_level_ || client.generation() != generation_) {
        // A new level: nothing of the old one carries over, and its sounds load now.
        seen_level_ = true;
        generation_ = client.generation();
        sound.stop_all_sounds();
        sound.precache(client.sound_names());
    }
    sound.set_listener(listener);
    for (const SoundEvent& e : client.sound_events()) {
        switch (e.kind) {
            case SoundEvent::Kind::Start:
                sound.start_sound(e.entity, e.channel, e.sound, e.origin, e.volume, e.attenuation);
                break;
            case SoundEvent::Kind::Stop:
                sound.stop_sound(e.entity, e.channel);
                break;
            case SoundEvent::Kind::Static:
                sound.add_static_sound(e.sound, e.origin, e.volume, e.attenuation);
                break;
        }
    }
    client.clear_sound_events();
    if (client.cd_track_messages() != cd_track_messages_) {
        cd_track_messages_ = client.cd_track_messages();
        sound.play_cd_track(client.cd_track(), true);  // Quake loops the level's track
    }
}

}  // namespace nq
