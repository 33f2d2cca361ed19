#include "technical/technical_cvars.h"

#include <algorithm>

namespace nq::npr::technical {
namespace {

using S = TechnicalSettings;

using cvar_parse::choice;
using cvar_parse::color;
using cvar_parse::flag;
using menu_line::range;
using menu_line::toggle;

// The bindings; the lambdas convert to plain function pointers.
const CvarBinding kBindings[] = {
    // ---- edges
    {"tech_silhouettes", "1", "draw silhouette edges (0/1)",
     [](const nqr_cvar& c, S& s) { s.edges.silhouettes = flag(c); }},
    {"tech_creases", "1", "draw ridge and valley creases (0/1)",
     [](const nqr_cvar& c, S& s) { s.edges.creases = flag(c); }},
    {"tech_crease_angle", "60", "dihedral angle (degrees) above which an edge is a crease",
     [](const nqr_cvar& c, S& s) {
         s.edges.crease_angle_degrees = std::clamp(c.value, 0.0f, 180.0f);
     }},
    {"tech_silhouette_width", "2", "silhouette width in pixels at 480 lines",
     [](const nqr_cvar& c, S& s) { s.edges.silhouette_width = std::clamp(c.value, 0.0f, 32.0f); }},
    {"tech_ridge_width", "1.5", "ridge width in pixels at 480 lines",
     [](const nqr_cvar& c, S& s) { s.edges.ridge_width = std::clamp(c.value, 0.0f, 32.0f); }},
    {"tech_valley_width", "1.5", "valley width in pixels at 480 lines",
     [](const nqr_cvar& c, S& s) { s.edges.valley_width = std::clamp(c.value, 0.0f, 32.0f); }},
    {"tech_silhouette_color", "0 0 0", "silhouette base colour (r g b, 0..1)",
     [](const nqr_cvar& c, S& s) { s.edges.silhouette_color = color(c); }},
    {"tech_ridge_color", "1 1 1", "ridge base colour (r g b, 0..1)",
     [](const nqr_cvar& c, S& s) { s.edges.ridge_color = color(c); }},
    {"tech_valley_color", "0.1 0.1 0.1", "valley base colour (r g b, 0..1)",
     [](const nqr_cvar& c, S& s) { s.edges.valley_color = color(c); }},
    {"tech_edge_colors", "1",
     "edge colours: 0 base colours, 1 white addition on creases, 2 white addition on all edges",
     [](const nqr_cvar& c, S& s) { s.edges.color_mode = EdgeColorMode(choice(c, 2)); }},
    {"tech_white", "0.4", "white addition w: edge = shaded colour + w (1 = white)",
     [](const nqr_cvar& c, S& s) { s.edges.white_w = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_fade", "1", "fade edges toward the model colour with distance (0/1)",
     [](const nqr_cvar& c, S& s) { s.edges.distance_fade = flag(c); }},
    {"tech_fade_distance", "1600",
     "blend threshold: distance at which edges reach the model colour",
     [](const nqr_cvar& c, S& s) { s.edges.fade_distance = std::max(c.value, 1.0f); }},
    {"tech_edge_offset", "0.002", "share of its depth an edge is pulled toward the eye",
     [](const nqr_cvar& c, S& s) { s.edges.depth_offset = std::clamp(c.value, 0.0f, 0.1f); }},
    {"tech_edge_merge", "0.5",
     "join a model's edges along chains while straight within this many pixels (0 = off)",
     [](const nqr_cvar& c, S& s) { s.edges.merge_pixels = std::clamp(c.value, 0.0f, 4.0f); }},
    {"tech_backface_lines", "1",
     "thick back-face lines: 0 never, 1 for models without clean adjacency, 2 always",
     [](const nqr_cvar& c, S& s) { s.edges.backface_lines = BackfaceLines(choice(c, 2)); }},
    {"tech_backface_width", "3", "back-face line width in pixels at 480 lines",
     [](const nqr_cvar& c, S& s) { s.edges.backface_width = std::clamp(c.value, 0.0f, 32.0f); }},
    {"tech_world_edges", "1", "silhouettes and creases of the world and brush entities (0/1)",
     [](const nqr_cvar& c, S& s) { s.edges.world_edges = flag(c); }},
    // ---- shading
    {"tech_shading", "1", "model shading: 0 classic, 1 Gooch cool-to-warm, 2 metal, 3 object id",
     [](const nqr_cvar& c, S& s) { s.shading.mode = ShadingMode(choice(c, 3)); }},
    {"tech_gooch_b", "0.4", "Gooch blue: k_blue = (0, 0, b)",
     [](const nqr_cvar& c, S& s) { s.shading.blue = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_gooch_y", "0.4", "Gooch yellow: k_yellow = (y, y, 0)",
     [](const nqr_cvar& c, S& s) { s.shading.yellow = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_gooch_alpha", "0.2", "Gooch alpha: k_cool = k_blue + alpha k_d",
     [](const nqr_cvar& c, S& s) { s.shading.alpha = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_gooch_beta", "0.6", "Gooch beta: k_warm = k_yellow + beta k_d",
     [](const nqr_cvar& c, S& s) { s.shading.beta = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_splashback", "1", "splash-back term on the tones (0/1)",
     [](const nqr_cvar& c, S& s) { s.shading.splashback = flag(c); }},
    {"tech_splashback_alpha", "0.76", "splash-back alpha_s in (alpha_s |cos| + 1 - alpha_s)^p",
     [](const nqr_cvar& c, S& s) { s.shading.splashback_alpha = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_splashback_p", "0.78", "splash-back exponent p",
     [](const nqr_cvar& c, S& s) { s.shading.splashback_p = std::clamp(c.value, 0.0f, 8.0f); }},
    {"tech_texture_blend", "0", "0: k_d is the skin's average colour; 1: the skin texel",
     [](const nqr_cvar& c, S& s) { s.shading.texture_blend = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_metal_bands", "12", "metal shading: bands across the model's height",
     [](const nqr_cvar& c, S& s) { s.shading.metal_bands = std::clamp(c.value, 0.0f, 256.0f); }},
    // ---- shadows
    {"tech_shadows", "1", "planar shadows under models (0/1)",
     [](const nqr_cvar& c, S& s) { s.shadows.enabled = flag(c); }},
    {"tech_shadow_penumbra", "1", "umbra + penumbra (1) or one hard shadow (0)",
     [](const nqr_cvar& c, S& s) { s.shadows.penumbra = flag(c); }},
    {"tech_shadow_color", "0 0 0", "shadow colour (r g b, 0..1)",
     [](const nqr_cvar& c, S& s) { s.shadows.color = color(c); }},
    {"tech_shadow_alpha", "0.5", "opacity of the hard shadow and of the umbra",
     [](const nqr_cvar& c, S& s) { s.shadows.alpha = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_shadow_penumbra_alpha", "0.2", "opacity of each penumbra projection",
     [](const nqr_cvar& c, S& s) { s.shadows.penumbra_alpha = std::clamp(c.value, 0.0f, 1.0f); }},
    {"tech_shadow_umbra_scale", "0.85", "umbra: the projection scaled about its centre",
     [](const nqr_cvar& c, S& s) { s.shadows.umbra_scale = std::clamp(c.value, 0.0f, 2.0f); }},
    {"tech_shadow_penumbra_offset", "4", "penumbra: sideways shift of each projection (units)",
     [](const nqr_cvar& c, S& s) { s.shadows.penumbra_offset = std::clamp(c.value, 0.0f, 64.0f); }},
    {"tech_shadow_max_drop", "512", "farthest floor below a model that receives its shadow",
     [](const nqr_cvar& c, S& s) { s.shadows.max_drop = std::clamp(c.value, 0.0f, 8192.0f); }},
    {"tech_shadow_distance", "1500",
     "models farther from the eye cast no shadow (fading out over the last quarter)",
     [](const nqr_cvar& c, S& s) { s.shadows.max_distance = std::max(c.value, 0.0f); }},
};

static_assert(std::size(kBindings) <= 64, "raise TechnicalCvars::kMaxCvars");

const char* const kShadingChoices[] = {"classic", "gooch", "metal", "object id"};
const char* const kEdgeColourChoices[] = {"base", "white creases", "white all"};
const char* const kBackfaceChoices[] = {"never", "if needed", "always"};

const nqr_menu_setting kMenuSettings[] = {
    toggle("tech_silhouettes", "Silhouettes"),
    toggle("tech_creases", "Creases"),
    toggle("tech_world_edges", "World edges"),
    range("tech_silhouette_width", "Silhouette width", 0.5f, 6, 0.5f),
    range("tech_crease_angle", "Crease angle", 10, 120, 5),
    menu_line::choice("tech_edge_colors", "Edge colours", kEdgeColourChoices),
    menu_line::choice("tech_backface_lines", "Back-face lines", kBackfaceChoices),
    toggle("tech_fade", "Distance fade"),
    menu_line::choice("tech_shading", "Shading", kShadingChoices),
    range("tech_gooch_b", "Gooch blue", 0, 1, 0.05f),
    range("tech_gooch_y", "Gooch yellow", 0, 1, 0.05f),
    toggle("tech_shadows", "Shadows"),
    toggle("tech_shadow_penumbra", "Soft shadows"),
};

}  // namespace

std::span<const nqr_menu_setting> technical_menu_settings() {
    return kMenuSettings;
}

std::span<const CvarBinding> technical_cvar_bindings() {
    return kBindings;
}

}  // namespace nq::npr::technical
