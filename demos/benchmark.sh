#!/usr/bin/env bash
# The benchmark as one command: every demo x style x size, styles interleaved within each round
# (and QuakeSpasm after them when it is installed), N rounds (demos/bench_timedemo.sh); then
# a style gallery (the same demo frame in every style, in one engine run) and the report
# (demos/bench_report.py): report.html (self-contained), report.md, charts as PNG.
#
# usage: demos/benchmark.sh [--quick] [--demos "demo demo2"] [--styles "classic technical illustrative"]
#                           [--sizes "640x480 1024x768"] [--runs N] [--peer quakespasm|none]
#                           [--gallery-frame N] [--out DIR]
#   --quick   demo.dem at 640x480, 2 rounds: under 5 minutes (numbers to check the tooling,
#             not to quote)
#   --peer    quakespasm: QuakeSpasm is a column (an error if it is not installed); none: not;
#             default: a column when /usr/games/quakespasm is installed
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Output in --out (default build/benchmark). The exit status is 1 when any run failed (the
# report still shows the cells that worked, and the failed ones as failed).
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=7,16
usage_on_error=1
demos="demo demo2"
styles="classic technical illustrative"
sizes="640x480 1024x768"
runs=3
peer=auto
gallery_frame=""  # per demo when not given: see frame_of
quality_frames=8   # consecutive frames for the line-flicker figure
out=$root/build/benchmark
while [ $# -gt 0 ]; do
    case $1 in
        --quick) demos="demo"; sizes="640x480"; runs=2; shift ;;
        --demos) demos=$2; shift 2 ;;
        --styles) styles=$2; shift 2 ;;
        --sizes) sizes=$2; shift 2 ;;
        --runs) runs=$2; shift 2 ;;
        --peer) peer=$2; shift 2 ;;
        --gallery-frame) gallery_frame=$2; shift 2 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
require_data
/usr/bin/python3 -c "import matplotlib" 2>/dev/null ||
    die "needs python3-matplotlib (scripts/install-deps.sh)"
case $peer in
    auto) if quakespasm_installed; then peer=quakespasm; else peer=none; fi ;;
    quakespasm) quakespasm_installed || die "QuakeSpasm or $quakespasm_tool is not installed" ;;
    none) ;;
    *) echo "$me: --peer quakespasm or none" >&2; exit 2 ;;
esac
rm -rf "$out"
mkdir -p "$out/gallery"

# The machine, as it was during the run (load averages before and after: these machines are
# shared, and the numbers mean little when others were busy).
loadavg() { cut -d' ' -f1-3 /proc/loadavg; }
load_before=$(loadavg)
started=$(date -u +%Y-%m-%dT%H:%M:%SZ)

echo "benchmark.sh: demos [$demos] styles [$styles] sizes [$sizes], $runs rounds, peer $peer"
"$root/demos/bench_timedemo.sh" --rounds "$runs" --plugins "$styles" --demos "$demos" \
    --res "$sizes" --peer "$peer" --out "$out" | grep --line-buffered -v '^|' || true

# The frame the gallery and the line quality look at: --gallery-frame, else one with models in
# view (LibreQuake's demo.dem: its monster gallery; demo2.dem: a row of weapons), else 760.
frame_of() {
    if [ -n "$gallery_frame" ]; then echo "$gallery_frame"; return; fi
    case $1 in
        demo2) echo 300 ;;
        *) echo 760 ;;
    esac
}

# The gallery: per demo, one engine run pauses at the frame and shoots it in every style.
first_size=${sizes%% *}
for demo in $demos; do
    frame=$(frame_of "$demo")
    shots="pause 1"
    for style in $styles; do
        shots="$shots; r_plugin $style; wait; wait; screenshot $out/gallery/${demo}_f${frame}_$style.png"
    done
    SDL_VIDEODRIVER=offscreen "$engine" -userdir "$out/user" -basedir "$data" -game lq1 \
        -width "${first_size%x*}" -height "${first_size#*x}" -window +con_notifytime 0 \
        +scr_centertime 0 +demo_at "$frame" "$shots; quit" +timedemo "$demo" +quit \
        > "$out/logs/gallery_$demo.log" 2>&1 ||
        echo "benchmark.sh: gallery of $demo failed (see $out/logs/gallery_$demo.log)" >&2
done

# Line quality of the technical style (demos/line_quality.sh): silhouette recall/precision on
# the gallery frame, flicker over $quality_frames consecutive frames from it. The other styles
# draw no lines (illustrative marks silhouettes with rim light), so only technical has these.
mkdir -p "$out/quality"
if [[ " $styles " == *" technical "* ]]; then
    for demo in $demos; do
        "$root/demos/line_quality.sh" --demo "$demo" --frame "$(frame_of "$demo")" \
            --frames "$quality_frames" --size "$first_size" --out "$out" ||
            echo "benchmark.sh: line quality of $demo failed" >&2
    done
fi

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -1)
/usr/bin/python3 - "$out/machine.json" <<PY
import json, sys
json.dump({
    "date (UTC)": "$started",
    "CPU": "$cpu",
    "cores": $(nproc),
    "load average before (1/5/15 min)": "$load_before",
    "load average after": "$(loadavg)",
    "kernel": "$(uname -sr)",
    "nprquake commit": "$(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)",
    "QuakeSpasm": "$([ "$peer" = quakespasm ] && dpkg-query -W -f='${Version}' quakespasm 2>/dev/null || echo 'not run')",
    "command": "demos/benchmark.sh --demos '$demos' --styles '$styles' --sizes '$sizes' --runs $runs --peer $peer",
}, open(sys.argv[1], "w"), indent=1)
PY
/usr/bin/python3 "$root/demos/bench_report.py" "$out" --gallery "$out/gallery" \
    --machine "$out/machine.json" > /dev/null
echo "benchmark.sh: $out/report.html, $out/report.md (load average before: $load_before, after: $(loadavg))"
grep -q '"failed":true' "$out/results.jsonl" && { echo "benchmark.sh: some runs FAILED (see report)" >&2; exit 1; }
exit 0
