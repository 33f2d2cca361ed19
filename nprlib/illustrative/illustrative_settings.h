// Every parameter of the illustrative style (Mitchell, Francke, Eng: "Illustrative Rendering in
// Team Fortress 2", NPAR 2007), with its default. The plugin fills this from its cvars
// (illustrative_cvars.h, one per field, documented in docs/console.md); the drawers only read
// it. Model defaults are Valve's player materials: Phong exponent 20, boost 0.3, Fresnel ranges
// (0.3, 1, 8), rim exponent 4, rim boost 2. A model's material file (material_file.h) overrides
// the per-model ones.
#pragma once

#include <string>

namespace nq::npr::illustrative {

// What the fragment shader outputs (ill_show): the final colour or one term on its own, as in
// the paper's figure 6.
enum class ShowTerm {
    final = 0,
    albedo = 1,          // k_d (team saturation applied)
    ambient = 2,         // a(n)
    warped_diffuse = 3,  // sum_i c_i w(...)
    diffuse_total = 4,   // k_d [a(n) + sum ...]
    specular = 5,        // the per-light max() with the rim half off
    rim = 6,             // the per-light rim half + the dedicated rim
    view_dependent = 7,  // everything equation 2 adds
};
inline constexpr int kShowTerms = 8;

// The per-model terms a material file may override.
struct MaterialParams {
    float phong_exponent = 20.0f;  // k_spec where the skin masks do not give one
    float phong_boost = 0.3f;
    float fresnel_ranges[3] = {0.3f, 1.0f, 8.0f};  // f_s at n.v = 1, at the middle, at grazing
    float rim_exponent = 4.0f;                     // k_rim: broad, constant per object
    float rim_boost = 2.0f;
    float ambient_scale = 1.0f;
    bool rim_light = true;
    bool rim_mask = true;            // k_r from the skin masks (else 1)
    bool exponent_from_skin = true;  // k_spec per texel from the skin masks (else phong_exponent)
    bool self_illum = true;          // fullbright skin texels glow
};

struct IllustrativeSettings {
    // View-independent: k_d [a(n) + sum_i c_i w((alpha (n.l_i) + beta)^gamma)].
    float half_lambert_alpha = 0.5f;
    float half_lambert_beta = 0.5f;
    float half_lambert_gamma = 1.0f;
    std::string warp_ramp = "tf2";  // built-in name or a path to a PNG / .lmp ramp image
    float ambient_scale = 1.0f;     // a(n), the ambient cube
    float light_scale = 1.0f;       // c_i, the entity's local lights
    int max_lights = 2;             // 0..4: lights per pixel, strongest first; the rest of the
                                    // engine's list joins the ambient cube
    // View-dependent terms.
    bool specular = true;
    bool rim = true;            // the rim half of the per-light max()
    bool dedicated_rim = true;  // (n.u) f_r k_r a(-v)
    MaterialParams material;    // defaults for models without a material file
    bool skin_masks = true;     // derive k_s, k_spec, k_r from the skin (skin_masks.h)
    // Models.
    bool smooth_normals = true;          // welded, crease-preserving normals (at registration)
    float crease_angle_degrees = 60.0f;  // sharper turns keep a hard edge
    float team_saturation = 1.5f;        // saturation boost of shirt/pants texels (1 = none)
    bool height_gradient = false;        // the paper's dark-feet-to-light-chest gradient
    float height_gradient_floor = 0.6f;  // brightness at the model's lowest point
    // World (at map load).
    bool abstract_world = true;  // edge-preserving smoothing of the world textures
    int abstract_radius = 2;     // Kuwahara radius in texels
    float world_saturation = 1.2f;
    float world_contrast = 1.15f;
    ShowTerm show = ShowTerm::final;  // ill_show: the final colour or one term alone
};

}  // namespace nq::npr::illustrative
