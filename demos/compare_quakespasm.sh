#!/usr/bin/env bash
# docs/images/classic_vs_quakespasm.jpg: one frame of demo.dem drawn by our `classic` renderer
# (left) and by QuakeSpasm 0.95 (right), side by side.
#
# Ours is the timedemo frame FRAME; QuakeSpasm plays the demo at normal speed and is grabbed
# after SECONDS (../shared/tools/quakespasm_timedemo.sh --shot). Around frame 301 the player
# stands still for several seconds, so both show the same view although QuakeSpasm's moment
# is only roughly the same (monsters may have moved).
#
# QuakeSpasm's own default.cfg sets viewsize 110 and scr_sbarscale 1.6; ours is given the same
# (our defaults are Quake's: viewsize 100, scr_sbarscale 1), so the two status bars compare.
#
# usage: demos/compare_quakespasm.sh [--frame N] [--seconds S] [--size WxH] [--out FILE.jpg]
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Needs ImageMagick (convert) and whatever quakespasm_timedemo.sh installs.
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=13,14
usage_on_error=1
frame=301
seconds=5
size=640x480
out=$root/docs/images/classic_vs_quakespasm.jpg
while [ $# -gt 0 ]; do
    case "$1" in
        --frame) frame=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
require_data
# The tool installs QuakeSpasm when it runs: the tool is all this needs.
[ -x "$quakespasm_tool" ] || die "$quakespasm_tool missing"
require_command convert "needs ImageMagick"
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT

SDL_VIDEODRIVER=offscreen "$engine" -basedir "$data" -game lq1 -userdir "$work/user" \
    -width "${size%x*}" -height "${size#*x}" +r_plugin classic +viewsize 110 +scr_sbarscale 1.6 \
    +demo_at "$frame" "screenshot $work/ours.png; quit" +timedemo demo >"$work/ours.log" 2>&1 \
    || { cat "$work/ours.log" >&2; exit 1; }
LQ1="$data/lq1" "$quakespasm_tool" --shot "$seconds" "$work/quakespasm.png" demo "$size" >&2
[ -f "$work/ours.png" ] && [ -f "$work/quakespasm.png" ] \
    || { echo "compare_quakespasm.sh: a screenshot is missing (KEEP=1 keeps $work)" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
convert "$work/ours.png" "$work/quakespasm.png" +append -quality 90 "$out"
echo "wrote $out"
