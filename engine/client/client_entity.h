// The client's record of one server entity, as fast updates and baselines build it, plus what
// the client derives from it each frame (lerped origin and angles, animation).
#pragma once

#include <array>
#include <cstdint>

#include "client/animation.h"
#include "formats/server_message.h"

namespace nq {

inline constexpr int kMaxClientEntities = 32768;  // entity numbers are 16-bit on the wire
inline constexpr size_t kMaxStaticEntities = 4096;

// Entity effect bits (svc updates' U_EFFECTS byte).
enum EntityEffect : int {
    kEffectBrightField = 1,  // particle field around the entity
    kEffectMuzzleFlash = 2,
    kEffectBrightLight = 4,
    kEffectDimLight = 8,
};

// FitzQuake's alpha encoding: 0 = default (opaque), 1 = invisible, 255 = opaque.
inline float decode_alpha(int encoded) {
    return encoded == 0 ? 1.0f : static_cast<float>(encoded - 1) / 254.0f;
}
inline constexpr int kAlphaInvisible = 1;

// An entity's animation memory plus the reasons to stop blending.
struct AnimationTracker {
    FrameLerp lerp;
    bool reset = true;               // snap at the next update: new entity or model, missed think
    bool reset_next_change = false;  // also snap at the frame change after (muzzle flashes)
};

// Records the frame the entity shows at client time `time`: a change starts a blend from the
// frame before, lasting `lerp_finish - time` when the server sent U_LERPFINISH (lerp_finish
// >= 0), else 0.1 s.
void track_frame(AnimationTracker& tracker, int frame, double time, double lerp_finish);

struct ClientEntity {
    EntityState baseline{};
    double msg_time = -1;  // server time (mtime[0]) of its latest update; -1: never updated
    std::array<Vec3, 2> msg_origins{};  // [0] latest update, [1] the one before
    std::array<Vec3, 2> msg_angles{};
    int model = 0;  // model index; 0 = none (not drawn)
    int frame = 0;
    int colormap = 0;  // 0, or 1..max_clients: use that player's colours
    int skin = 0;
    int effects = 0;
    int alpha = 0;  // encoded as decode_alpha() expects
    float scale = 1;
    bool force_link = false;  // no previous update to lerp from: snap to the latest
    bool step = false;        // U_NOLERP: the server moves it in steps; never lerped
    double lerp_finish = -1;  // absolute server time from U_LERPFINISH; < 0 when not sent
    float random_phase = 0;   // animation phase drawn at each model change (sync_type 1 models)
    AnimationTracker anim;

    // Derived by ClientState::prepare_frame.
    Vec3 origin{};
    Vec3 angles{};
    bool visible = false;  // has a model and was in the latest server message
};

struct StaticEntity {
    EntityState state;
    FrameLerp lerp;  // frame never changes; frame groups still cycle
};

}  // namespace nq
