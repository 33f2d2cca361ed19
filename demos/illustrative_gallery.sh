#!/usr/bin/env bash
# The pictures in docs/illustrative.md: the same demo frames in `classic`, `technical` and
# `illustrative`; the paper's figure 6 decomposition (albedo, ambient cube, warped diffuse,
# specular, rims) on Quake models; and one picture per illustrative setting, on the showroom and
# on a paused demo frame.
#
# usage: demos/illustrative_gallery.sh [--out DIR]      (default docs/images/illustrative)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Needs ImageMagick. The status bar and the screen tints are off, so the pictures show the models.
set -euo pipefail
style=illustrative
compare_styles="classic technical illustrative"
source "$(dirname "$0")/gallery_lib.sh"
out=$root/docs/images/illustrative
[ "${1:-}" = "--out" ] && out=$2

# The cvar defaults, written out so a user's config cannot leak in.
defaults="ill_show 0; ill_ramp tf2; ill_halflambert_alpha 0.5; ill_halflambert_beta 0.5;
ill_halflambert_gamma 1; ill_ambient 1; ill_lights 1; ill_max_lights 2; ill_specular 1; ill_rim 1;
ill_dedicated_rim 1; ill_phong_exponent 20; ill_phong_boost 0.3; ill_fresnel_ranges \"0.3 1 8\";
ill_rim_exponent 4; ill_rim_boost 2; ill_skin_masks 1; ill_team_saturation 1.5;
ill_height_gradient 0; ill_height_floor 0.6; ill_smooth_normals 1; ill_crease_angle 60;
ill_abstract 1; ill_abstract_radius 2; ill_world_saturation 1.2; ill_world_contrast 1.15"

# Pictures: "name|commands". Settings applied at load reload the plugin (r_plugin), and so does
# the picture after them, to load with the defaults again.
settings=(
    "final|ill_show 0"
    "albedo|ill_show 1"
    "ambient_cube|ill_show 2"
    "warped_diffuse|ill_show 3"
    "diffuse|ill_show 4"
    "specular|ill_show 5"
    "rim|ill_show 6"
    "view_dependent|ill_show 7"
    "ramp_neutral|ill_ramp neutral"
    "ramp_cel|ill_ramp cel"
    "lambert|ill_halflambert_alpha 1; ill_halflambert_beta 0"
    "gamma_2|ill_halflambert_gamma 2"
    "ambient_0|ill_ambient 0"
    "ambient_2|ill_ambient 2"
    "lights_0|ill_lights 0"
    "lights_1_max|ill_max_lights 1"
    "lights_4_max|ill_max_lights 4"
    "specular_off|ill_specular 0"
    "phong_boost_1|ill_phong_boost 1"
    "phong_exponent_5|ill_skin_masks 0; ill_phong_exponent 5"
    "masks_off|ill_skin_masks 0"
    "fresnel_flat|ill_fresnel_ranges 1"
    "rim_off|ill_rim 0; ill_dedicated_rim 0"
    "dedicated_rim_off|ill_dedicated_rim 0"
    "rim_boost_6|ill_rim_boost 6"
    "rim_exponent_1|ill_rim_exponent 1"
    "team_1|ill_team_saturation 1"
    "team_3|ill_team_saturation 3"
    "height_gradient|ill_height_gradient 1"
    "height_gradient_0.3|ill_height_gradient 1; ill_height_floor 0.3"
    "smooth_off|ill_smooth_normals 0; r_plugin illustrative"
    "smooth_on|r_plugin illustrative"
    "crease_20|ill_crease_angle 20; r_plugin illustrative"
    "abstract_off|ill_abstract 0; r_plugin illustrative"
    "abstract_radius_4|ill_abstract_radius 4; ill_world_saturation 1.5; ill_world_contrast 1.4; r_plugin illustrative"
    "abstract_on|r_plugin illustrative"
)

frames="300 600 760"
gallery_init
gallery_showroom
gallery_demo "$frames"
compare_sheets "$frames"
group terms "the terms alone (ill_show): albedo, ambient cube, warped diffuse, diffuse" \
    albedo ambient_cube warped_diffuse diffuse
group view_terms "specular, rims, both, final" specular rim view_dependent final
group ramps "warp ramp: tf2, neutral, cel" final ramp_neutral ramp_cel
group half_lambert "half-Lambert (default), Lambert, gamma 2" final lambert gamma_2
group ambient "ambient cube x0, x1, x2" ambient_0 final ambient_2
group lights "local lights off, one per pixel, two (default), four" lights_0 lights_1_max final \
    lights_4_max
group specular "specular off, default, boost 1, exponent 5" specular_off final phong_boost_1 \
    phong_exponent_5
group masks "skin masks off / on, flat Fresnel" masks_off final fresnel_flat
group rims "rims off, dedicated rim off, default, rim boost 6, rim exponent 1" rim_off \
    dedicated_rim_off final rim_boost_6 rim_exponent_1
group team "team saturation 1, 1.5, 3" team_1 final team_3
group height "height gradient off, floor 0.6, floor 0.3" final height_gradient height_gradient_0.3
group normals "MDL vertex normals / smooth (60 degrees) / crease angle 20" smooth_off smooth_on \
    crease_20
group abstraction "world abstraction off / on / radius 4 with more saturation and contrast" \
    abstract_off abstract_on abstract_radius_4
echo "illustrative_gallery.sh: pictures in $out"
