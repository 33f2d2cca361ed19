// What the server's game code shares within a level: the QuakeC VM and its layout, the collision
// world, which edicts are in use, the physics settings (cvars) and the clock. Physics, player
// movement, monster movement and the builtins all work on one GameState.
#pragma once

#include <cstdint>
#include <string_view>

#include "server/edict_pool.h"
#include "server/progs_layout.h"
#include "vm/vm.h"

namespace nq::server {

class World;

// Quake's sv_* movement cvars, with their defaults.
struct PhysicsSettings {
    float gravity = 800;
    float max_speed = 320;
    float friction = 4;
    float edge_friction = 2;
    float stop_speed = 100;
    float accelerate = 10;
    float max_velocity = 2000;
    float water_accelerate = 10;  // Quake uses sv_accelerate in water too
    float water_friction = 4;
    float step_size = 18;
    bool no_step = false;
};

// One client's movement command for a frame (clc_move).
struct UserCmd {
    vm::Vec3f view_angles{};
    float forward_move = 0, side_move = 0, up_move = 0;
    int buttons = 0;  // bit 0 attack, bit 1 jump
    int impulse = 0;
};

// Where sounds the engine itself starts (water splashes, landing) go: the server's message
// writer. Samples are names as precached ("misc/h2ohit1.wav").
class SoundSink {
  public:
    virtual ~SoundSink() = default;
    virtual void start_sound(uint32_t edict, int channel, std::string_view sample, float volume,
                             float attenuation) = 0;
};

struct GameState {
    vm::Vm& vm;
    const ProgsLayout& layout;
    World& world;
    EdictPool& edicts;
    PhysicsSettings settings;
    double time = 0;       // server time of the frame being run
    float frame_time = 0;  // seconds this frame advances
    SoundSink* sounds = nullptr;

    const FieldOffsets& f() const { return layout.fields; }
    const GlobalOffsets& g() const { return layout.globals; }
};

}  // namespace nq::server
