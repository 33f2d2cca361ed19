// The `illustrative` renderer plugin: Team Fortress 2's illustrative shading on Quake, drawn by
// nprlib's IllustrativeRenderer (classic world with abstracted textures underneath, TF2-shaded
// models on top), with its cvars (illustrative_cvars.h) read every frame.
#include "abi/plugin_shell.h"
#include "illustrative/illustrative_cvars.h"
#include "illustrative/illustrative_renderer.h"

namespace {

struct IllustrativeStyle {
    using Renderer = nq::npr::illustrative::IllustrativeRenderer;
    using Cvars = nq::npr::illustrative::IllustrativeCvars;
    static constexpr const char* kName = "illustrative";
    static constexpr const char* kDescription =
        "Team Fortress 2's illustrative shading: warped diffuse, ambient cubes, rim light";
    static std::span<const nqr_menu_setting> menu_settings() {
        return nq::npr::illustrative::illustrative_menu_settings();
    }
};

}  // namespace

NQR_DEFINE_PLUGIN(IllustrativeStyle)
