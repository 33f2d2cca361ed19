#!/usr/bin/env bash
# The pictures in docs/obscurance.md: the same demo frames in `classic`, `technical` and
# `illustrative` with volumetric obscurance on, and one picture per vo_* setting (most with
# vo_show 1, the obscurance alone) on the showroom and on a paused demo frame.
#
# usage: demos/obscurance_gallery.sh [--out DIR]      (default docs/images/obscurance)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Needs ImageMagick.
set -euo pipefail
style=classic
compare_styles="classic technical illustrative"
engine_args="+vo_enable 1"
source "$(dirname "$0")/gallery_lib.sh"
out=$root/docs/images/obscurance
[ "${1:-}" = "--out" ] && out=$2

# The cvar defaults, written out so a user's config cannot leak in.
defaults="vo_enable 1; vo_mode lines5; vo_radius 24; vo_radius2 0; vo_dual_min 0; vo_thickness 32;
vo_strength 1; vo_normal 1; vo_shift 1; vo_blur 1; vo_half 0; vo_show 0"

settings=(
    "off|vo_enable 0"
    "on|vo_show 0"
    "half_strength|vo_strength 0.5"
    "show|vo_show 1"
    "lines9|vo_show 1; vo_mode lines9"
    "points12|vo_show 1; vo_mode points12"
    "points33|vo_show 1; vo_mode points33"
    "radius_12|vo_show 1; vo_radius 12"
    "radius_48|vo_show 1; vo_radius 48"
    "dual_24_96|vo_show 1; vo_radius2 96"
    "dual_min|vo_show 1; vo_radius2 96; vo_dual_min 1"
    "thickness_0|vo_show 1; vo_thickness 0"
    "normal_off|vo_show 1; vo_normal 0"
    "shift_off|vo_show 1; vo_shift 0"
    "blur_off|vo_show 1; vo_blur 0"
    "half|vo_show 1; vo_half 1"
)

frames="300 600 760"
gallery_init
gallery_showroom
gallery_demo "$frames"
compare_sheets "$frames"
group effect "obscurance off, on, strength 0.5, alone" off on half_strength show
group modes "lines5 (default), lines9, points12, points33 (alone)" show lines9 points12 points33
group radius "radius 12, 24 (default), 48; radii 24 and 96 by product, by minimum" radius_12 \
    show radius_48 dual_24_96 dual_min
group options "default, samples turned only (vo_shift 0), thickness 0 (infinite), no normal clamp, \
no blur, half resolution" show shift_off thickness_0 normal_off blur_off half
echo "obscurance_gallery.sh: pictures in $out"
