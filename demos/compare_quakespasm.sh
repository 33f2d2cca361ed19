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
root=$(cd "$(dirname "$0")/.." && pwd)
data=${NPRQ_DATA:-$root/../shared/data}
build=${BUILD:-$root/build/release}
frame=301
seconds=5
size=640x480
out=$root/docs/images/classic_vs_quakespasm.jpg
while [ $# -gt 0 ]; do
    case "$1" in
        --frame) frame=$2; shift 2 ;;
        --seconds) seconds=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) echo "usage: $0 [--frame N] [--seconds S] [--size WxH] [--out FILE.jpg]" >&2; exit 2 ;;
    esac
done
engine=$build/bin/nprquake
peer=$root/../shared/tools/quakespasm_timedemo.sh
[ -x "$engine" ] || { echo "compare_quakespasm.sh: build first ($engine missing)" >&2; exit 1; }
[ -d "$data/lq1" ] || { echo "compare_quakespasm.sh: no game data at $data/lq1" >&2; exit 1; }
[ -x "$peer" ] || { echo "compare_quakespasm.sh: $peer missing" >&2; exit 1; }
command -v convert >/dev/null || { echo "compare_quakespasm.sh: needs ImageMagick" >&2; exit 1; }
work=$(mktemp -d)
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT

SDL_VIDEODRIVER=offscreen "$engine" -basedir "$data" -game lq1 -userdir "$work/user" \
    -width "${size%x*}" -height "${size#*x}" +r_plugin classic +viewsize 110 +scr_sbarscale 1.6 \
    +demo_at "$frame" "screenshot $work/ours.png; quit" +timedemo demo >"$work/ours.log" 2>&1 \
    || { cat "$work/ours.log" >&2; exit 1; }
LQ1="$data/lq1" "$peer" --shot "$seconds" "$work/quakespasm.png" demo "$size" >&2
[ -f "$work/ours.png" ] && [ -f "$work/quakespasm.png" ] \
    || { echo "compare_quakespasm.sh: a screenshot is missing (KEEP=1 keeps $work)" >&2; exit 1; }
mkdir -p "$(dirname "$out")"
convert "$work/ours.png" "$work/quakespasm.png" +append -quality 90 "$out"
echo "wrote $out"
