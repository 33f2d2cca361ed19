// The console's cvars, registered with descriptions through the host's CvarRegistry:
//   con_notifytime  3    seconds a printed line stays at the top of the screen (console closed)
//   scr_centertime  2    seconds a centre-screen message stays
//   scr_conspeed    300  slide speed, in lines of Quake's 200-line screen per second (0: instant)
//   con_scale       0    text scale, a whole multiple of the 8x8 font; 0 picks one from the
//                        screen size
#pragma once

#include "host/cvar_registry.h"

namespace nq {

struct ConsoleCvars {
    const Cvar* notify_time = nullptr;
    const Cvar* center_time = nullptr;
    const Cvar* slide_speed = nullptr;
    const Cvar* scale = nullptr;
};

// Registers (or re-registers) the cvars. Never fails: the specs are valid.
ConsoleCvars register_console_cvars(CvarRegistry& cvars);

}  // namespace nq
