#!/usr/bin/env bash
# The pictures in docs/technical.md: the same demo frames in `classic` and `technical`, and one
# picture per technical setting (the paper's figures 5-13: white addition, distance fade, Gooch,
# splash-back, shadow alpha, scale and offset, ...), on the showroom and on a paused demo frame.
#
# usage: demos/technical_gallery.sh [--out DIR]      (default docs/images/technical)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Needs ImageMagick (montage, convert) for the labelled contact sheets. The status bar and the
# screen tints are off, so the pictures show the models.
set -euo pipefail
style=technical
source "$(dirname "$0")/gallery_lib.sh"
out=$root/docs/images/technical
[ "${1:-}" = "--out" ] && out=$2

# The defaults every picture starts from (the cvar defaults, written out so a user's config
# cannot leak in).
defaults="tech_shading 1; tech_silhouettes 1; tech_creases 1; tech_edge_colors 1; tech_white 0.4;
tech_fade 1; tech_fade_distance 1600; tech_splashback 1; tech_shadows 1; tech_shadow_penumbra 1;
tech_shadow_alpha 0.5; tech_shadow_umbra_scale 0.85; tech_shadow_penumbra_offset 4;
tech_backface_lines 1; tech_texture_blend 0; tech_world_edges 1"

# Pictures: "name|commands" (commands on top of the defaults).
settings=(
    "classic_shading|tech_shading 0"
    "gooch|tech_shading 1"
    "metal|tech_shading 2"
    "splashback_off|tech_splashback 0"
    "splashback_on|tech_splashback 1"
    "white_0|tech_edge_colors 2; tech_white 0"
    "white_0.4|tech_edge_colors 2; tech_white 0.4"
    "white_1|tech_edge_colors 2; tech_white 1"
    "base_colours|tech_edge_colors 0"
    "fade_off|tech_fade 0"
    "fade_300|tech_fade_distance 300"
    "fade_1600|tech_fade_distance 1600"
    "shadow_hard|tech_shadow_penumbra 0"
    "shadow_alpha_0.3|tech_shadow_alpha 0.3"
    "shadow_alpha_0.8|tech_shadow_alpha 0.8"
    "umbra_scale_0.6|tech_shadow_umbra_scale 0.6"
    "umbra_scale_1|tech_shadow_umbra_scale 1"
    "penumbra_offset_2|tech_shadow_penumbra_offset 2"
    "penumbra_offset_12|tech_shadow_penumbra_offset 12"
    "backface_always|tech_backface_lines 2"
    "texture_blend_1|tech_texture_blend 1"
    "edges_off|tech_silhouettes 0; tech_creases 0; tech_world_edges 0"
)

frames="300 600 760"
gallery_init
gallery_showroom
gallery_demo "$frames"
compare_sheets "$frames"
group shading "shading: classic, Gooch 98, metal (Gooch 99)" classic_shading gooch metal
group splashback "splash-back off / on" splashback_off splashback_on
group white_addition "white addition on all edges, w = 0, 0.4, 1" white_0 white_0.4 white_1
group edge_colours "edge colours: base colours / white addition on creases (default)" \
    base_colours gooch
group distance_fade "distance fade: off, blend threshold 300, 1600" fade_off fade_300 fade_1600
group shadow_alpha "shadow alpha 0.3 / 0.5 / 0.8" shadow_alpha_0.3 gooch shadow_alpha_0.8
group shadow_penumbra "one hard shadow / umbra + penumbra" shadow_hard gooch
group umbra_scale "umbra scale 0.6 / 0.85 / 1" umbra_scale_0.6 gooch umbra_scale_1
group penumbra_offset "penumbra offset 2 / 4 / 12" penumbra_offset_2 gooch penumbra_offset_12
group backface_lines "edges off / adjacency edges / back-face lines on every model" \
    edges_off gooch backface_always
group texture_blend "texture blend 0 / 1" gooch texture_blend_1
echo "technical_gallery.sh: pictures in $out"
