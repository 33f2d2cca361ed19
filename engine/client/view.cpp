#include "client/view.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "client/client_math.h"

namespace nq {
namespace {

constexpr float kDeadRoll = 80;         // the camera lies on its side when health is gone
constexpr float kStairClimbSpeed = 80;  // units per second the smoothed eye rises
constexpr float kMaxStairLag = 12;

Vec3 view_entity_origin(const ClientState& client) {
    const ClientEntity* e = client.entity(client.view_entity());
    return e ? e->origin : Vec3{};
}

Vec3 view_entity_angles(const ClientState& client) {
    const ClientEntity* e = client.entity(client.view_entity());
    return e ? e->angles : Vec3{};
}

// How far below the real eye height the smoothed eye stays while climbing stairs.
float stair_offset(const ClientState& client, ViewState& state, float z, bool enabled) {
    const PlayerState& p = client.player();
    const float rising = z - state.smoothed_z;
    if (enabled && state.has_smoothed_z && p.on_ground && rising > 0) {
        float step = static_cast<float>(std::max(0.0, client.time() - client.old_time()));
        state.smoothed_z = std::min(state.smoothed_z + step * kStairClimbSpeed, z);
        state.smoothed_z = std::max(state.smoothed_z, z - kMaxStairLag);
        return state.smoothed_z - z;
    }
    state.smoothed_z = z;
    state.has_smoothed_z = true;
    return 0;
}

void fill_contents(ViewResult& view, const ViewSettings& settings) {
    if (!settings.contents_at) return;
    view.eye_contents = settings.contents_at(settings.contents_user, view.origin);
    view.underwater = view.eye_contents <= kContentsWater && view.eye_contents >= kContentsLava;
}

ViewResult intermission_view(const ClientState& client, const ViewSettings& settings) {
    ViewResult view;
    view.intermission = true;
    view.origin = view_entity_origin(client);
    view.angles = view_entity_angles(client);
    view.in_water = client.player().in_water;
    fill_contents(view, settings);
    return view;
}

ViewModelPlacement place_view_model(const ClientState& client, const ViewSettings& settings,
                                    const Vec3& eye, const Vec3& view_angles, float bob) {
    const PlayerState& p = client.player();
    ViewModelPlacement gun;
    gun.model = p.stats[kStatWeapon];
    gun.frame = p.stats[kStatWeaponFrame];
    gun.alpha = decode_alpha(p.weapon_alpha);
    gun.visible = settings.draw_view_model && gun.model > 0 &&
                  static_cast<size_t>(gun.model) < client.model_names().size() &&
                  p.stats[kStatHealth] > 0 && !(p.items & kItemInvisibility);
    gun.angles = {-view_angles[0], view_angles[1], 0};
    const Basis basis = angle_vectors(view_angles);
    gun.origin = vmad(eye, bob * 0.4f, basis.forward);
    gun.origin[2] += settings.view_model_lift;
    return gun;
}

}  // namespace

float view_bob(const ViewSettings& settings, double time, const Vec3& velocity) {
    if (!settings.bob || !(settings.bob_cycle > 0)) return 0;
    constexpr float kPi = std::numbers::pi_v<float>;
    double cycle = std::fmod(time, static_cast<double>(settings.bob_cycle));
    if (cycle < 0) cycle += settings.bob_cycle;
    float phase = static_cast<float>(cycle) / settings.bob_cycle;
    const float up = std::clamp(settings.bob_up, 0.01f, 0.99f);
    phase = phase < up ? kPi * phase / up : kPi + kPi * (phase - up) / (1.0f - up);
    // Bob is proportional to horizontal speed, with a constant part and a sine part.
    float speed = std::sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1]);
    float bob = speed * settings.bob_amount;
    bob = bob * 0.3f + bob * 0.7f * std::sin(phase);
    return std::clamp(bob, -7.0f, 4.0f);
}

float view_roll(const ViewSettings& settings, const Vec3& angles, const Vec3& velocity) {
    if (!settings.roll || !(settings.roll_speed > 0)) return 0;
    float side = vdot(velocity, angle_vectors(angles).right);
    float sign = side < 0 ? -1.0f : 1.0f;
    side = std::fabs(side);
    side = side < settings.roll_speed ? side * settings.roll_angle / settings.roll_speed
                                      : settings.roll_angle;
    return side * sign;
}

ViewResult compute_view(const ClientState& client, ViewState& state, const ViewSettings& settings) {
    if (client.intermission() != Intermission::None) return intermission_view(client, settings);
    const PlayerState& p = client.player();
    ViewResult view;
    view.in_water = p.in_water;

    const Vec3 body = view_entity_origin(client);
    const float bob = view_bob(settings, client.time(), p.velocity);
    view.origin = body;
    view.origin[2] += static_cast<float>(p.view_height) + bob;

    Vec3 angles = p.view_angles;
    angles[2] += view_roll(settings, angles, p.velocity);
    if (p.stats[kStatHealth] <= 0) angles[2] = kDeadRoll;

    view.view_model = place_view_model(client, settings, view.origin, angles, bob);
    view.angles = vadd(angles, p.punch_angles);  // the kick moves the camera, not the gun

    const float stairs = stair_offset(client, state, body[2], settings.smooth_stairs);
    view.origin[2] += stairs;
    view.view_model.origin[2] += stairs;
    fill_contents(view, settings);
    return view;
}

float view_model_lift_for(float viewsize) {
    // Quake keeps roughly as much of the weapon in sight as the status bar leaves visible.
    if (viewsize == 110.0f || viewsize == 90.0f) return 1.0f;
    if (viewsize == 100.0f) return 2.0f;
    if (viewsize == 80.0f) return 0.5f;
    return 0.0f;
}

}  // namespace nq
