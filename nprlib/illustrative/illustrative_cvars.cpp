#include "illustrative/illustrative_cvars.h"

#include <algorithm>

namespace nq::npr::illustrative {
namespace {

using S = IllustrativeSettings;
using cvar_parse::choice;
using cvar_parse::flag;
using menu_line::range;
using menu_line::toggle;

float clamped(const nqr_cvar& c, float lo, float hi) {
    return std::clamp(c.value, lo, hi);
}

// The bindings; the lambdas convert to plain function pointers.
const CvarBinding kBindings[] = {
    // ---- view-independent terms
    {"ill_halflambert_alpha", "0.5", "half-Lambert scale alpha in (alpha (n.l) + beta)^gamma",
     [](const nqr_cvar& c, S& s) { s.half_lambert_alpha = clamped(c, 0, 1); }},
    {"ill_halflambert_beta", "0.5", "half-Lambert bias beta",
     [](const nqr_cvar& c, S& s) { s.half_lambert_beta = clamped(c, 0, 1); }},
    {"ill_halflambert_gamma", "1", "half-Lambert exponent gamma",
     [](const nqr_cvar& c, S& s) { s.half_lambert_gamma = clamped(c, 0.1f, 8); }},
    {"ill_ramp", "tf2",
     "warp ramp: tf2, neutral, cel, or a PNG / .lmp image in the game's files (its middle row)",
     [](const nqr_cvar& c, S& s) { s.warp_ramp = c.string ? c.string : "tf2"; }},
    {"ill_ambient", "1", "scale of the ambient cube term a(n)",
     [](const nqr_cvar& c, S& s) { s.ambient_scale = clamped(c, 0, 8); }},
    {"ill_lights", "1", "scale of the local lights c_i",
     [](const nqr_cvar& c, S& s) { s.light_scale = clamped(c, 0, 8); }},
    {"ill_max_lights", "2",
     "local lights shaded per pixel (0..4, strongest first; the others join the ambient cube)",
     [](const nqr_cvar& c, S& s) { s.max_lights = choice(c, 4); }},
    // ---- view-dependent terms (a model's .mat file overrides the material ones)
    {"ill_specular", "1", "Phong specular term (0/1)",
     [](const nqr_cvar& c, S& s) { s.specular = flag(c); }},
    {"ill_rim", "1", "per-light rim term (0/1)", [](const nqr_cvar& c, S& s) { s.rim = flag(c); }},
    {"ill_dedicated_rim", "1", "dedicated rim from the ambient cube on upward faces (0/1)",
     [](const nqr_cvar& c, S& s) { s.dedicated_rim = flag(c); }},
    {"ill_phong_exponent", "20",
     "specular exponent where neither the skin masks nor a .mat file give one",
     [](const nqr_cvar& c, S& s) { s.material.phong_exponent = clamped(c, 1, 1000); }},
    {"ill_phong_boost", "0.3", "specular boost (Source's $phongboost)",
     [](const nqr_cvar& c, S& s) { s.material.phong_boost = clamped(c, 0, 100); }},
    {"ill_fresnel_ranges", "0.3 1 8",
     "specular Fresnel f_s at facing, middle and grazing view (Source's $phongfresnelranges)",
     [](const nqr_cvar& c, S& s) {
         cvar_parse::numbers<3>(c, 0, 10, 1, s.material.fresnel_ranges);
     }},
    {"ill_rim_exponent", "4", "rim exponent k_rim (broad)",
     [](const nqr_cvar& c, S& s) { s.material.rim_exponent = clamped(c, 0.1f, 100); }},
    {"ill_rim_boost", "2", "rim boost (per-light and dedicated rims)",
     [](const nqr_cvar& c, S& s) { s.material.rim_boost = clamped(c, 0, 100); }},
    {"ill_skin_masks", "1",
     "derive specular mask, exponent and rim mask from each skin texel's palette colour (0/1)",
     [](const nqr_cvar& c, S& s) { s.skin_masks = flag(c); }},
    // ---- models
    {"ill_smooth_normals", "1",
     "welded, crease-keeping smooth normals (0/1; applies to models loaded afterwards)",
     [](const nqr_cvar& c, S& s) { s.smooth_normals = flag(c); }},
    {"ill_crease_angle", "60",
     "smooth normals keep a hard edge where faces turn by more (degrees; at model load)",
     [](const nqr_cvar& c, S& s) { s.crease_angle_degrees = clamped(c, 0, 180); }},
    {"ill_team_saturation", "1.5",
     "saturation boost of shirt and pants texels on player-coloured models (1 = none)",
     [](const nqr_cvar& c, S& s) { s.team_saturation = clamped(c, 0, 4); }},
    {"ill_height_gradient", "0", "the paper's dark-feet-to-light-chest gradient (0/1)",
     [](const nqr_cvar& c, S& s) { s.height_gradient = flag(c); }},
    {"ill_height_floor", "0.6", "brightness of the gradient at a model's lowest point",
     [](const nqr_cvar& c, S& s) { s.height_gradient_floor = clamped(c, 0, 1); }},
    // ---- world (at map load)
    {"ill_abstract", "1",
     "abstract the world's textures: Kuwahara filter, saturation, contrast (0/1; at map load)",
     [](const nqr_cvar& c, S& s) { s.abstract_world = flag(c); }},
    {"ill_abstract_radius", "2", "Kuwahara radius in texels (0 = no filter; at map load)",
     [](const nqr_cvar& c, S& s) { s.abstract_radius = std::clamp(c.integer, 0, 8); }},
    {"ill_world_saturation", "1.2", "world texture saturation (1 = unchanged; at map load)",
     [](const nqr_cvar& c, S& s) { s.world_saturation = clamped(c, 0, 4); }},
    {"ill_world_contrast", "1.15", "world texture value contrast (1 = unchanged; at map load)",
     [](const nqr_cvar& c, S& s) { s.world_contrast = clamped(c, 0, 4); }},
    // ---- debugging
    {"ill_show", "0",
     "show one term: 0 final, 1 albedo, 2 ambient cube, 3 warped diffuse, 4 diffuse, "
     "5 specular, 6 rim, 7 view-dependent",
     [](const nqr_cvar& c, S& s) { s.show = ShowTerm(choice(c, kShowTerms - 1)); }},
};

static_assert(std::size(kBindings) <= 64, "raise CvarSet's MaxCvars");

const char* const kShowChoices[] = {"final",   "albedo",   "ambient", "warped",
                                    "diffuse", "specular", "rim",     "view-dep"};

const nqr_menu_setting kMenuSettings[] = {
    toggle("ill_specular", "Specular"),
    toggle("ill_rim", "Rim light"),
    toggle("ill_dedicated_rim", "Dedicated rim"),
    range("ill_ambient", "Ambient cube", 0, 2, 0.1f),
    range("ill_lights", "Local lights", 0, 2, 0.1f),
    range("ill_phong_boost", "Specular boost", 0, 2, 0.1f),
    range("ill_rim_boost", "Rim boost", 0, 4, 0.25f),
    range("ill_team_saturation", "Team saturation", 1, 3, 0.1f),
    toggle("ill_height_gradient", "Height gradient"),
    toggle("ill_abstract", "Abstract world"),
    menu_line::choice("ill_show", "Show term", kShowChoices),
};

}  // namespace

std::span<const CvarBinding> illustrative_cvar_bindings() {
    return kBindings;
}

std::span<const nqr_menu_setting> illustrative_menu_settings() {
    return kMenuSettings;
}

}  // namespace nq::npr::illustrative
