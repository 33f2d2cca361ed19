#include "console/console_cvars.h"

#include <cassert>

namespace nq {
namespace {

const Cvar* register_numeric(CvarRegistry& cvars, const char* name, const char* value,
                             uint32_t flags, float min, float max, const char* description) {
    const Cvar* cvar = cvars.register_cvar(CvarSpec{name, value, flags, description, min, max});
    assert(cvar && "console cvar specs are valid");
    return cvar;
}

}  // namespace

ConsoleCvars register_console_cvars(CvarRegistry& cvars) {
    ConsoleCvars out;
    out.notify_time = register_numeric(
        cvars, "con_notifytime", "3", 0, 0.0f, 60.0f,
        "seconds a printed line stays at the top of the screen while the console is closed");
    out.center_time = register_numeric(cvars, "scr_centertime", "2", 0, 0.0f, 60.0f,
                                       "seconds a centre-screen message stays");
    out.slide_speed = register_numeric(
        cvars, "scr_conspeed", "300", kCvarArchive, 0.0f, 100000.0f,
        "console slide speed in lines of a 200-line screen per second (0: no slide)");
    out.scale = register_numeric(
        cvars, "con_scale", "0", kCvarArchive, 0.0f, 16.0f,
        "console text size as a whole multiple of 8x8 pixels (0: chosen from the screen size)");
    return out;
}

}  // namespace nq
