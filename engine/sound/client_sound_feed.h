// The client's side of sound (Quake's CL_ParseStartSoundPacket, CL_ParseStaticSound and the
// cd track): once per frame, after the demo or the game has applied its messages, hands the
// sound system what the client recorded: a new level's precache list (loaded right away),
// the sounds started, stopped and placed, the CD track, and the listener (the view).
#pragma once

#include <cstdint>

#include "client/client_state.h"
#include "sound/sound_system.h"

namespace nq {

// The listener of a view: its origin and the right vector of its angles.
Listener listener_for_view(const Vec3& origin, const Vec3& angles, int view_entity);

class ClientSoundFeed {
  public:
    // Takes the client's sound events (clearing them) into `sound`, with `listener` as the
    // place they are heard from.
    void feed(ClientState& client, SoundSystem& sound, const Listener& listener);
    // The next feed starts over as if the client were new (a new demo or game).
    void reset() { *this = ClientSoundFeed{}; }

  private:
    bool seen_level_ = false;
    uint32_t generation_ = 0;
    uint32_t cd_track_messages_ = 0;
};

}  // namespace nq
