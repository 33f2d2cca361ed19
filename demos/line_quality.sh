#!/usr/bin/env bash
# Line quality of the technical style on one demo (bin/edgequality, the rules the tests use):
# one engine run pauses on N consecutive frames from --frame and shoots each twice, as the
# object-id reference (tech_shading 3, no lines) and with its silhouettes over it; silhouette
# recall/precision on the first frame, flicker over all of them. Appends one JSON line to
# DIR/quality.jsonl; shots in DIR/quality/DEMO, the engine's log in DIR/logs/quality_DEMO.log.
#
# usage: demos/line_quality.sh --demo NAME --frame N [--frames N] [--size WxH] --out DIR
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Exit status 1 when the run or the measurement failed.
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=8,9
usage_on_error=1
demo=""
frame=""
frames=8
size=640x480
out=""
while [ $# -gt 0 ]; do
    case $1 in
        --demo) demo=$2; shift 2 ;;
        --frame) frame=$2; shift 2 ;;
        --frames) frames=$2; shift 2 ;;
        --size) size=$2; shift 2 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
[ -n "$demo" ] && [ -n "$frame" ] && [ -n "$out" ] || { usage >&2; exit 2; }
require_build edgequality
require_data

reference_settings="tech_shading 3; tech_silhouettes 0; tech_creases 0; tech_world_edges 0"
reference_settings="$reference_settings; tech_shadows 0; tech_fade 0; tech_edge_colors 0"
frames_dir=$out/quality/$demo
mkdir -p "$frames_dir" "$out/logs"
at_frames=()
pairs=()
for ((k = 0; k < frames; k++)); do
    f=$((frame + k))
    at_frames+=(+demo_at "$f" "pause 1; $reference_settings; wait; wait; screenshot $frames_dir/ref_$f.png; tech_silhouettes 1; wait; wait; screenshot $frames_dir/lines_$f.png; pause 0")
    pairs+=("$frames_dir/ref_$f.png" "$frames_dir/lines_$f.png")
done
if SDL_VIDEODRIVER=offscreen "$engine" -userdir "$out/user_quality" -basedir "$data" \
    -game lq1 -width "${size%x*}" -height "${size#*x}" -window \
    +con_notifytime 0 +scr_centertime 0 +scr_drawhud 0 +gl_polyblend 0 \
    +r_plugin technical "${at_frames[@]}" +timedemo "$demo" +quit \
    > "$out/logs/quality_$demo.log" 2>&1 &&
    "$build/bin/edgequality" silhouettes "${pairs[0]}" "${pairs[1]}" --json \
        > "$frames_dir/silhouettes.json" &&
    "$build/bin/edgequality" flicker "${pairs[@]}" --json > "$frames_dir/flicker.json"; then
    printf '{"demo": "%s", "style": "technical", "size": "%s", "first_frame": %d, "frames": %d, "silhouettes": %s, "flicker": %s}\n' \
        "$demo" "$size" "$frame" "$frames" \
        "$(tr -d '\n' < "$frames_dir/silhouettes.json")" \
        "$(tr -d '\n' < "$frames_dir/flicker.json")" >> "$out/quality.jsonl"
else
    echo "line_quality.sh: line quality of $demo failed (see $out/logs/quality_$demo.log)" >&2
    exit 1
fi
