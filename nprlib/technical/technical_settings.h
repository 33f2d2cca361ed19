// Every parameter of the technical-illustration style, with its default. The plugin fills this
// from its cvars (one cvar per field, see docs/console.md); nprlib's technical drawers only read
// it. Defaults: Gooch et al. 1998 for the cool-to-warm tones, Batchelder & Wysocki's
// "Technical Quake" (2005) for splash-back, white addition, distance fade and shadows.
#pragma once

#include <glm/vec3.hpp>

namespace nq::npr::technical {

// object_id: every entity flat in a saturated colour picked by its number (a reference image
// for edge tests and for researchers comparing edge detectors).
enum class ShadingMode { classic = 0, gooch = 1, metal = 2, object_id = 3 };

// How edge colours are made.
enum class EdgeColorMode {
    base = 0,           // each edge kind draws its own base colour (Gooch 99: black and white)
    white_creases = 1,  // ridges: shaded + w; valleys: shaded * (1 - w); silhouettes: base colour
    white_all = 2       // white addition on every edge: silhouettes and ridges shaded + w
};

// When the paper's thick back-face lines replace true silhouettes.
enum class BackfaceLines { never = 0, unclean_models = 1, always = 2 };

struct EdgeSettings {
    bool silhouettes = true;
    bool creases = true;
    float crease_angle_degrees = 60.0f;  // an edge whose faces turn by more is a crease
    float silhouette_width = 2.0f;       // pixels (at 480 lines; scaled with the viewport)
    float ridge_width = 1.5f;
    float valley_width = 1.5f;
    glm::vec3 silhouette_color{0.0f};
    glm::vec3 ridge_color{1.0f};
    glm::vec3 valley_color{0.1f};
    EdgeColorMode color_mode = EdgeColorMode::white_creases;
    float white_w = 0.4f;  // white addition: 1 = pure white, 0.1 keeps the model colour
    bool distance_fade = true;
    float fade_distance = 1600.0f;  // blend threshold: edges take the model colour from here on
    float depth_offset = 0.002f;    // edges pulled toward the eye by this share of their depth
    float merge_pixels = 0.5f;      // alias edge chains: straight within this many pixels -> one
    BackfaceLines backface_lines = BackfaceLines::unclean_models;
    float backface_width = 3.0f;  // pixels, like the widths above
    bool world_edges = true;      // silhouettes and creases of brush geometry (BSP shared edges)
};

struct ShadingSettings {
    ShadingMode mode = ShadingMode::gooch;
    // Gooch 98: k_cool = (0, 0, b) + alpha * k_d, k_warm = (y, y, 0) + beta * k_d.
    float blue = 0.4f, yellow = 0.4f, alpha = 0.2f, beta = 0.6f;
    bool splashback = true;
    float splashback_alpha = 0.76f;  // (alpha_s * |cos theta| + (1 - alpha_s))^p, cos = n . l
    float splashback_p = 0.78f;
    float texture_blend = 0.0f;  // 0: k_d is the skin's average colour; 1: the texel itself
    float metal_bands = 12.0f;   // metal mode: anisotropic bands across the model's height
};

struct ShadowSettings {
    bool enabled = true;
    bool penumbra = true;  // umbra + penumbra; off: one hard shadow
    glm::vec3 color{0.0f};
    float alpha = 0.5f;            // the hard shadow, and the umbra
    float penumbra_alpha = 0.2f;   // each of the two penumbra projections
    float umbra_scale = 0.85f;     // umbra: the projection scaled down about its centre
    float penumbra_offset = 4.0f;  // world units each penumbra projection is shifted sideways
    float max_drop = 512.0f;       // farthest floor a shadow is cast on, below the model
    float max_distance = 1500.0f;  // models farther from the eye cast no shadow
};

struct TechnicalSettings {
    EdgeSettings edges;
    ShadingSettings shading;
    ShadowSettings shadows;
};

}  // namespace nq::npr::technical
