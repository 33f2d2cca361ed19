// The `technical` renderer plugin: technical illustration of Quake, drawn by nprlib's
// TechnicalRenderer (classic world textures underneath, NPR models and edges on top), with its
// cvars (technical_cvars.h) read every frame.
#include "abi/plugin_shell.h"
#include "technical/technical_cvars.h"
#include "technical/technical_renderer.h"

namespace {

struct TechnicalStyle {
    using Renderer = nq::npr::technical::TechnicalRenderer;
    using Cvars = nq::npr::technical::TechnicalCvars;
    static constexpr const char* kName = "technical";
    static constexpr const char* kDescription =
        "technical illustration: silhouettes, creases, Gooch shading, umbra/penumbra shadows";
    static std::span<const nqr_menu_setting> menu_settings() {
        return nq::npr::technical::technical_menu_settings();
    }
};

}  // namespace

NQR_DEFINE_PLUGIN(TechnicalStyle)
