// The per-frame work: settle the client clock against the last two server messages, move
// every entity to its interpolated place, run entity effects (lights, trails, bright fields),
// animation bookkeeping, beams, explosion sprites, particles and light styles.
#include <algorithm>
#include <cmath>

#include "client/client_math.h"
#include "client/client_state.h"

namespace nq {
namespace {

constexpr float kTeleportDistance = 100;  // a jump this long in one update is not a motion
constexpr double kMaxMessageGap = 0.1;    // longer gaps between messages are not blended over

}  // namespace

void ClientState::prepare_frame(LerpMode mode) {
    const float frac = settle_lerp_point(mode);
    lerp_fraction_ = frac;
    const float dt = static_cast<float>(std::max(0.0, time_ - old_time_));
    dlights_.decay(time_, dt);
    lerp_player(frac);
    relink_entities(frac);
    track_frame(view_model_anim_, player_.stats[kStatWeaponFrame], time_, -1.0);
    build_temp_entities();
    particles_.update(time_, dt, settings_.gravity);
    light_styles_.evaluate(time_, style_values_);
}

// Where the client clock stands between the two latest messages, as a 0..1 fraction. The
// clock is pulled back inside the interval when it strays out by more than 1%.
float ClientState::settle_lerp_point(LerpMode mode) {
    double gap = message_times_[0] - message_times_[1];
    if (mode == LerpMode::Snap || !(gap > 0)) {
        time_ = message_times_[0];
        return 1.0f;
    }
    if (gap > kMaxMessageGap) {
        message_times_[1] = message_times_[0] - kMaxMessageGap;
        gap = kMaxMessageGap;
    }
    double frac = (time_ - message_times_[1]) / gap;
    if (frac < 0) {
        if (frac < -0.01) time_ = message_times_[1];
        frac = 0;
    } else if (frac > 1) {
        if (frac > 1.01) time_ = message_times_[0];
        frac = 1;
    }
    return static_cast<float>(frac);
}

void ClientState::lerp_player(float frac) {
    PlayerState& p = player_;
    for (int i = 0; i < 3; ++i) {
        p.velocity[i] =
            p.message_velocity[1][i] + frac * (p.message_velocity[0][i] - p.message_velocity[1][i]);
        // Demo playback: the view turns as recorded in the block headers.
        p.view_angles[i] = lerp_angle(p.block_view_angles[1][i], p.block_view_angles[0][i], frac);
    }
}

void ClientState::relink_entities(float frac) {
    for (size_t i = 1; i < entities_.size(); ++i) {
        relink_entity(static_cast<int>(i), entities_[i], frac);
    }
}

void ClientState::relink_entity(int number, ClientEntity& e, float frac) {
    e.visible = false;
    if (e.model == 0) return;
    if (e.msg_time != message_times_[0]) {
        // Not in the latest message: the server no longer sends it (removed or out of sight).
        e.model = 0;
        e.anim.reset = true;
        return;
    }
    const Vec3 previous_origin = e.origin;
    if (e.force_link) {
        e.origin = e.msg_origins[0];
        e.angles = e.msg_angles[0];
    } else {
        float f = frac;
        const Vec3 delta = vsub(e.msg_origins[0], e.msg_origins[1]);
        for (float d : delta) {
            if (std::fabs(d) > kTeleportDistance) f = 1;
        }
        e.origin = vmad(e.msg_origins[1], f, delta);
        for (int j = 0; j < 3; ++j)
            e.angles[j] = lerp_angle(e.msg_angles[1][j], e.msg_angles[0][j], f);
    }
    e.force_link = false;

    const ModelInfo& info = model_info(e.model);
    if (info.flags & kEfRotate) e.angles[1] = angle_mod(100.0f * static_cast<float>(time_));
    entity_effects(number, e);
    model_trail(number, info, previous_origin, e.origin);

    e.anim.lerp.syncbase = info.sync_type == 1 ? e.random_phase : 0.0f;
    track_frame(e.anim, e.frame, time_, e.lerp_finish);
    e.visible = true;
}

void ClientState::entity_effects(int number, ClientEntity& e) {
    const double time = time_;
    if (e.effects & kEffectBrightField) effects_.bright_field(time, e.origin);
    if (e.effects & kEffectMuzzleFlash) {
        DynamicLight& light = dlights_.allocate(number, time);
        const Basis basis = angle_vectors(e.angles);
        light.origin = vmad(vadd(e.origin, {0, 0, 16}), 18, basis.forward);
        light.radius = static_cast<float>(200 + (random_.rand15() & 31));
        light.minlight = 32;
        light.die = time + 0.1;
        // The flash comes with a muzzle-flare frame that looks wrong half-blended.
        AnimationTracker& anim = number == view_entity_ ? view_model_anim_ : e.anim;
        anim.reset = true;
        anim.reset_next_change = true;
    }
    if (e.effects & kEffectBrightLight) {
        DynamicLight& light = dlights_.allocate(number, time);
        light.origin = vadd(e.origin, {0, 0, 16});
        light.radius = static_cast<float>(400 + (random_.rand15() & 31));
        light.die = time + 0.001;
    }
    if (e.effects & kEffectDimLight) {
        DynamicLight& light = dlights_.allocate(number, time);
        light.origin = e.origin;
        light.radius = static_cast<float>(200 + (random_.rand15() & 31));
        light.die = time + 0.001;
    }
}

void ClientState::model_trail(int number, const ModelInfo& info, const Vec3& from, const Vec3& to) {
    const int32_t flags = info.flags;
    const double time = time_;
    if (flags & kEfGib) {
        effects_.trail(time, from, to, TrailKind::Blood);
    } else if (flags & kEfZomGib) {
        effects_.trail(time, from, to, TrailKind::SlightBlood);
    } else if (flags & kEfTracer) {
        effects_.trail(time, from, to, TrailKind::Tracer);
    } else if (flags & kEfTracer2) {
        effects_.trail(time, from, to, TrailKind::Tracer2);
    } else if (flags & kEfRocket) {
        effects_.trail(time, from, to, TrailKind::Rocket);
        DynamicLight& light = dlights_.allocate(number, time);
        light.origin = to;
        light.radius = 200;
        light.die = time + 0.01;
    } else if (flags & kEfGrenade) {
        effects_.trail(time, from, to, TrailKind::Smoke);
    } else if (flags & kEfTracer3) {
        effects_.trail(time, from, to, TrailKind::Voor);
    }
}

void ClientState::build_temp_entities() {
    temp_entities_.clear();
    const ClientEntity* viewer = entity(view_entity_);
    const Vec3 view_origin = viewer ? viewer->origin : Vec3{};
    beams_.build_segments(time_, view_entity_, view_origin, random_, temp_entities_);

    // Client-side explosion sprites play their frames at 10 per second, then vanish.
    constexpr size_t kFallbackExplosionFrames = 6;  // s_explod.spr's frame count
    const ModelInfo& info = model_info(client_models_.explosion);
    const size_t frames = info.frames.empty() ? kFallbackExplosionFrames : info.frames.size();
    for (ExplosionSprite& x : explosions_) {
        if (x.start < 0) continue;
        // A clock pulled back a little after the spawn shows the first frame.
        const double frame = std::max(0.0, std::floor((time_ - x.start) * 10.0));
        if (!(frame < static_cast<double>(frames))) {
            x.start = -1;
            continue;
        }
        temp_entities_.push({client_models_.explosion, x.origin, {}, static_cast<int>(frame)});
    }
}

}  // namespace nq
