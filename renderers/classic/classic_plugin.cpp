// The `classic` renderer plugin: the faithful GLQuake look, drawn entirely by nprlib's classic
// drawers. It implements every hook itself, so the engine's defaults stay idle while it runs.
#include "abi/plugin_shell.h"
#include "classic/classic_renderer.h"

namespace {

struct ClassicStyle {
    using Renderer = nq::npr::classic::ClassicRenderer;
    using Cvars = nq::npr::NoStyleCvars;
    static constexpr const char* kName = "classic";
    static constexpr const char* kDescription =
        "the GLQuake look: textures, lightmaps, sky, liquids, models, sprites, particles";
    static std::span<const nqr_menu_setting> menu_settings() { return {}; }  // none of its own
};

}  // namespace

NQR_DEFINE_PLUGIN(ClassicStyle)
