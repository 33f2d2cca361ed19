// The camera of a frame and the view (weapon) model, from the client state, as Quake's view
// code places them: the eye sits view_height above the view entity's interpolated origin, with
// the demo's recorded view angles plus the punch angles (weapon kick), a little velocity roll
// and bob, and a smoothed climb up stairs. During an intermission the camera takes the view
// entity's own origin and angles and no weapon is drawn.
//
// Whether the eye is under water depends on the map (leaf contents), which the client does not
// know: set ViewSettings::contents_at to let compute_view() ask the engine, or fill
// ViewResult::underwater afterwards.
#pragma once

#include "client/animation.h"
#include "client/client_state.h"

namespace nq {

// Leaf contents values (BSP) that count as being under a liquid.
inline constexpr int kContentsWater = -3;
inline constexpr int kContentsSlime = -4;
inline constexpr int kContentsLava = -5;

struct ViewSettings {
    bool bob = true;  // cl_bob 0.02, cl_bobcycle 0.6, cl_bobup 0.5
    float bob_amount = 0.02f;
    float bob_cycle = 0.6f;
    float bob_up = 0.5f;
    bool roll = true;  // cl_rollangle 2, cl_rollspeed 200
    float roll_angle = 2.0f;
    float roll_speed = 200.0f;
    bool smooth_stairs = true;
    bool draw_view_model = true;
    // Lifts the weapon so that as much of it shows as at Quake's default screen size (100);
    // view_model_lift_for(viewsize) gives Quake's lift for other screen sizes.
    float view_model_lift = 2.0f;
    // The map's contents at a point (kContents* values), or null.
    int (*contents_at)(void* user, const Vec3& point) = nullptr;
    void* contents_user = nullptr;
};

// What the view remembers from frame to frame (the smoothed eye height on stairs).
struct ViewState {
    float smoothed_z = 0;
    bool has_smoothed_z = false;
};

struct ViewModelPlacement {
    bool visible = false;
    int model = 0;  // model index (the clientdata weapon)
    Vec3 origin{};
    // Quake's entity angle convention: the pitch is the negated view pitch, so the weapon
    // takes the same model-matrix rule as every alias entity the server sends.
    Vec3 angles{};
    int frame = 0;
    float alpha = 1;
};

struct ViewResult {
    Vec3 origin{};  // the eye
    Vec3 angles{};  // pitch, yaw, roll in degrees
    bool intermission = false;
    bool in_water = false;    // the server's clientdata: the player's waist is in a liquid
    bool underwater = false;  // the eye is in a liquid (only when contents_at is set)
    int eye_contents = 0;     // contents_at(origin), 0 when unknown
    ViewModelPlacement view_model;
};

ViewResult compute_view(const ClientState& client, ViewState& state,
                        const ViewSettings& settings = {});

// How far Quake raises the weapon at screen size `viewsize` (the `viewsize` cvar): 2 units at
// 100, 1 at 110 and 90, 0.5 at 80, none at 120 or any other size.
float view_model_lift_for(float viewsize);

// The vertical bob of the eye for the horizontal speed of `velocity` at client time `time`.
float view_bob(const ViewSettings& settings, double time, const Vec3& velocity);
// The roll added for sideways speed.
float view_roll(const ViewSettings& settings, const Vec3& angles, const Vec3& velocity);

}  // namespace nq
