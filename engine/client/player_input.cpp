#include "client/player_input.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <string>

namespace nq {

namespace {

struct ButtonName {
    const char* name;
    PlayerInput::Button button;
};

constexpr ButtonName kButtons[] = {
    {"forward", PlayerInput::kForward},   {"back", PlayerInput::kBack},
    {"moveleft", PlayerInput::kMoveLeft}, {"moveright", PlayerInput::kMoveRight},
    {"moveup", PlayerInput::kMoveUp},     {"movedown", PlayerInput::kMoveDown},
    {"left", PlayerInput::kLeft},         {"right", PlayerInput::kRight},
    {"lookup", PlayerInput::kLookUp},     {"lookdown", PlayerInput::kLookDown},
    {"speed", PlayerInput::kSpeed},       {"strafe", PlayerInput::kStrafe},
    {"attack", PlayerInput::kAttack},     {"jump", PlayerInput::kJump},
    {"mlook", PlayerInput::kMLook},       {"klook", PlayerInput::kKLook},
};

struct CvarDefault {
    const char* name;
    const char* value;
    const char* description;
};

constexpr CvarDefault kCvars[] = {
    {"cl_forwardspeed", "200", "forward speed (x2 with cl_run or +speed)"},
    {"cl_backspeed", "200", "backward speed"},
    {"cl_sidespeed", "350", "strafing speed"},
    {"cl_upspeed", "200", "swimming/flying up and down speed"},
    {"cl_movespeedkey", "2", "speed factor while running"},
    {"cl_yawspeed", "140", "turning speed of +left/+right, degrees per second"},
    {"cl_pitchspeed", "150", "looking speed of +lookup/+lookdown, degrees per second"},
    {"cl_anglespeedkey", "1.5", "turning speed factor while running"},
    {"cl_run", "1", "always run"},
    {"sensitivity", "3", "mouse speed"},
    {"m_pitch", "0.022", "mouse pitch factor (negative: inverted mouse)"},
    {"m_yaw", "0.022", "mouse yaw factor"},
    {"m_forward", "1", "mouse forward factor (mouse move without freelook)"},
    {"m_side", "0.8", "mouse strafe factor"},
    {"freelook", "1", "the mouse always looks around (+mlook held for good)"},
    {"lookstrafe", "0", "the mouse strafes instead of turning while looking"},
    {"lookspring", "0", "the view recentres when +mlook is released"},
};

// Which key pressed it ("+forward w" from a binding): a number for the key's name; -2 when
// typed in the console or a script.
int key_of(const CommandArgs& args) {
    if (args.argc() < 2) return -2;
    return int(std::hash<std::string>{}(args.argv(1)) & 0x3fffffff);
}

}  // namespace

PlayerInput::PlayerInput(CommandSystem& commands) : commands_(commands) {
    for (const ButtonName& b : kButtons) {
        const Button button = b.button;
        commands_.add_command(std::string("+") + b.name,
                              [this, button](const CommandArgs& a) { press(button, a); });
        commands_.add_command(std::string("-") + b.name,
                              [this, button](const CommandArgs& a) { release(button, a); });
    }
    commands_.add_command(
        "impulse",
        [this](const CommandArgs& a) {
            impulse_ = a.argc() > 1 ? std::atoi(a.argv(1).c_str()) : 0;
        },
        "impulse N: sends impulse N to the game (weapon change, cheats)");
    for (const CvarDefault& c : kCvars) {
        CvarSpec spec;
        spec.name = c.name;
        spec.default_value = c.value;
        spec.flags = kCvarArchive;
        spec.description = c.description;
        commands_.cvars().register_cvar(spec);
    }
}

PlayerInput::~PlayerInput() {
    for (const ButtonName& b : kButtons) {
        commands_.remove_command(std::string("+") + b.name);
        commands_.remove_command(std::string("-") + b.name);
    }
    commands_.remove_command("impulse");
}

void PlayerInput::press(Button b, const CommandArgs& args) {
    const int key = key_of(args);
    ButtonState& s = buttons_[b];
    if (key == s.keys[0] || key == s.keys[1]) return;  // repeating
    if (s.keys[0] == -1) {
        s.keys[0] = key;
    } else if (s.keys[1] == -1) {
        s.keys[1] = key;
    } else {
        commands_.print("Three keys down for a button!");
    }
}

void PlayerInput::release(Button b, const CommandArgs& args) {
    const int key = key_of(args);
    ButtonState& s = buttons_[b];
    if (key == -2) {  // typed "-forward": release whatever holds it
        s.keys = {-1, -1};
    } else if (s.keys[0] == key) {
        s.keys[0] = -1;
    } else if (s.keys[1] == key) {
        s.keys[1] = -1;
    }
    if (b == kMLook && !held(kMLook) && cvar("freelook") == 0 && cvar("lookspring") != 0) {
        view_angles_[0] = 0;
    }
}

void PlayerInput::release_all() {
    buttons_.fill({});
}

float PlayerInput::cvar(const char* name) const {
    const Cvar* c = commands_.cvars().find(name);
    return c ? c->value() : 0.0f;
}

void PlayerInput::add_mouse(float dx, float dy) {
    mouse_dx_ += dx;
    mouse_dy_ += dy;
}

void PlayerInput::adjust_angles(float frame_time) {
    const bool fast = held(kSpeed) != (cvar("cl_run") != 0);
    const float speed = fast ? frame_time * cvar("cl_anglespeedkey") : frame_time;
    if (!held(kStrafe)) {
        view_angles_[1] -= speed * cvar("cl_yawspeed") * float(held(kRight));
        view_angles_[1] += speed * cvar("cl_yawspeed") * float(held(kLeft));
        view_angles_[1] = std::fmod(view_angles_[1], 360.0f);
    }
    if (held(kKLook)) {
        view_angles_[0] -= speed * cvar("cl_pitchspeed") * float(held(kForward));
        view_angles_[0] += speed * cvar("cl_pitchspeed") * float(held(kBack));
    }
    view_angles_[0] -= speed * cvar("cl_pitchspeed") * float(held(kLookUp));
    view_angles_[0] += speed * cvar("cl_pitchspeed") * float(held(kLookDown));
    view_angles_[0] = std::clamp(view_angles_[0], -70.0f, 80.0f);  // Quake's pitch limits
    view_angles_[2] = std::clamp(view_angles_[2], -50.0f, 50.0f);
}

MoveCommand PlayerInput::build_move(float frame_time) {
    adjust_angles(frame_time);
    MoveCommand cmd;
    const bool strafe = held(kStrafe);
    if (strafe) {
        cmd.side += cvar("cl_sidespeed") * float(held(kRight));
        cmd.side -= cvar("cl_sidespeed") * float(held(kLeft));
    }
    cmd.side += cvar("cl_sidespeed") * float(held(kMoveRight));
    cmd.side -= cvar("cl_sidespeed") * float(held(kMoveLeft));
    cmd.up += cvar("cl_upspeed") * float(held(kMoveUp));
    cmd.up -= cvar("cl_upspeed") * float(held(kMoveDown));
    if (!held(kKLook)) {
        cmd.forward += cvar("cl_forwardspeed") * float(held(kForward));
        cmd.forward -= cvar("cl_backspeed") * float(held(kBack));
    }
    if (held(kSpeed) != (cvar("cl_run") != 0)) {
        const float k = cvar("cl_movespeedkey");
        cmd.forward *= k;
        cmd.side *= k;
        cmd.up *= k;
    }

    // Mouse: look while freelook or +mlook, else move.
    const float sens = cvar("sensitivity");
    const float mx = mouse_dx_ * sens, my = mouse_dy_ * sens;
    mouse_dx_ = mouse_dy_ = 0;
    const bool mlook = held(kMLook) || cvar("freelook") != 0;
    if (strafe || (cvar("lookstrafe") != 0 && mlook)) {
        cmd.side += cvar("m_side") * mx;
    } else {
        view_angles_[1] -= cvar("m_yaw") * mx;
    }
    if (mlook && !strafe) {
        view_angles_[0] = std::clamp(view_angles_[0] + cvar("m_pitch") * my, -70.0f, 80.0f);
    } else if (strafe) {
        cmd.up -= cvar("m_forward") * my;
    } else {
        cmd.forward -= cvar("m_forward") * my;
    }

    cmd.view_angles = view_angles_;
    cmd.buttons = (held(kAttack) ? 1 : 0) | (held(kJump) ? 2 : 0);
    cmd.impulse = impulse_;
    impulse_ = 0;
    return cmd;
}

}  // namespace nq
