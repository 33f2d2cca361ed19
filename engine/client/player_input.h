// The player's controls, as Quake's cl_input.c has them: held buttons (+forward, +attack, ...,
// each held by up to two keys), impulses, mouse look, and the movement cvars. Once a frame
// build_move() turns them into the view angles and the move a clc_move carries.
//
// Cvars (defaults as Quake, except freelook and always-run on, as QuakeSpasm players expect):
// cl_forwardspeed 200, cl_backspeed 200, cl_sidespeed 350, cl_upspeed 200, cl_movespeedkey 2,
// cl_yawspeed 140, cl_pitchspeed 150, cl_anglespeedkey 1.5, cl_run 1 (always run: speeds x2),
// sensitivity 3, m_pitch 0.022 (negative inverts), m_yaw 0.022, m_forward 1, m_side 0.8,
// freelook 1, lookstrafe 0, lookspring 0.
#pragma once

#include <array>
#include <cstdint>

#include "host/command_system.h"

namespace nq {

struct MoveCommand {
    std::array<float, 3> view_angles{};  // pitch, yaw, roll in degrees
    float forward = 0, side = 0, up = 0;
    int buttons = 0;  // bit 0 attack, bit 1 jump
    int impulse = 0;
};

class PlayerInput {
  public:
    // Registers the commands and cvars on `commands`; they stay until the PlayerInput goes.
    explicit PlayerInput(CommandSystem& commands);
    ~PlayerInput();
    PlayerInput(const PlayerInput&) = delete;
    PlayerInput& operator=(const PlayerInput&) = delete;

    // Relative mouse motion since the last frame, in pixels.
    void add_mouse(float dx, float dy);
    // The command for a frame of `frame_time` seconds; clears the impulse and mouse motion.
    MoveCommand build_move(float frame_time);

    std::array<float, 3>& view_angles() { return view_angles_; }
    // Every held button up (focus lost, level change).
    void release_all();

    enum Button {
        kForward,
        kBack,
        kMoveLeft,
        kMoveRight,
        kMoveUp,
        kMoveDown,
        kLeft,
        kRight,
        kLookUp,
        kLookDown,
        kSpeed,
        kStrafe,
        kAttack,
        kJump,
        kMLook,
        kKLook,
        kButtonCount
    };
    bool held(Button b) const { return buttons_[b].held(); }

  private:
    struct ButtonState {
        std::array<int, 2> keys{-1, -1};  // key numbers holding it; -2 = typed in the console
        bool held() const { return keys[0] != -1 || keys[1] != -1; }
    };

    void press(Button b, const CommandArgs& args);
    void release(Button b, const CommandArgs& args);
    float cvar(const char* name) const;
    void adjust_angles(float frame_time);

    CommandSystem& commands_;
    std::array<ButtonState, kButtonCount> buttons_{};
    std::array<float, 3> view_angles_{};
    float mouse_dx_ = 0, mouse_dy_ = 0;
    int impulse_ = 0;
};

}  // namespace nq
