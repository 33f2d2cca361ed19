#!/usr/bin/env bash
# ThreadSanitizer loop: the engine and its plugins built with -fsanitize=thread (the `tsan`
# preset) run what uses threads, again and again: level loads (the ambient-cube bake runs on
# worker threads while the level's models register and the classic style's brush textures are
# filtered on threads of their own), renderer swaps in mid-level, a demo with obscurance on,
# and the benchmark's line-quality command (demos/line_quality.sh). Every report is kept; the
# summary counts them and names each distinct race by its first frames.
#
# usage: scripts/tsan_loop.sh [--rounds N] [--out DIR]
#   --rounds  how many times the whole loop runs (default 3)
#   --out     where logs and reports go (default build/tsan/loop)
# env:   NPRQ_DATA (default ../shared/data)
# Exit status 1 when ThreadSanitizer reported anything or a run failed.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
data=${NPRQ_DATA:-$root/../shared/data}
rounds=3
out=$root/build/tsan/loop
while [ $# -gt 0 ]; do
    case $1 in
        --rounds) rounds=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) sed -n '9,11p' "$0" >&2; exit 2 ;;
    esac
done
[ -d "$data/lq1" ] || { echo "tsan_loop.sh: no game data at $data/lq1 (set NPRQ_DATA)" >&2; exit 1; }
cmake --preset tsan > /dev/null
cmake --build --preset tsan -j "$(nproc)"
engine=$root/build/tsan/bin/nprquake
rm -rf "$out"
mkdir -p "$out/reports" "$out/logs" "$out/user/lq1"
# Reports go to files (one per process); the runs go on after a report to find the next one.
export TSAN_OPTIONS="halt_on_error=0 second_deadlock_stack=1 history_size=4 log_path=$out/reports/tsan suppressions=$root/scripts/tsan.supp"
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy

# Each map three times over, a style swap in mid-level, obscurance on in one of them.
waits() { for ((i = 0; i < $1; i++)); do echo wait; done; }
{
    for map in start e2m3 lq1m1 lqdm4_a6; do
        echo "map $map"; waits 40
        echo "r_plugin technical"; waits 20
        echo "r_plugin illustrative"; echo "vo_enable 1"; waits 20
        echo "vo_enable 0"; echo "r_plugin classic"; waits 10
    done
    echo "echo tsan_loop: maps done"
    echo quit
} > "$out/user/lq1/tsan_maps.cfg"

failed=0
run() {  # run NAME COMMAND...: one logged run; a failed run counts
    local name=$1; shift
    if "$@" > "$out/logs/$name.log" 2>&1; then
        echo "tsan_loop.sh: $name ok"
    else
        echo "tsan_loop.sh: $name FAILED (exit $?; $out/logs/$name.log)"
        failed=1
    fi
}
base_args=(-userdir "$out/user" -basedir "$data" -game lq1 -width 320 -height 240 -window)
for ((round = 1; round <= rounds; round++)); do
    run "maps_$round" "$engine" "${base_args[@]}" +exec tsan_maps.cfg
    run "demo_$round" "$engine" "${base_args[@]}" +demo_at 200 "r_plugin technical" \
        +demo_at 400 "r_plugin illustrative; vo_enable 1" +demo_at 600 "r_plugin classic" \
        +timedemo demo2 +quit
    run "quality_$round" env BUILD="$root/build/tsan" NPRQ_DATA="$data" \
        bash demos/line_quality.sh --demo demo --frame 300 --frames 2 --size 320x240 \
        --out "$out/quality_$round"
done

# Summary: how many reports, and each distinct race by the first two frames of both accesses.
reports=$(cat "$out"/reports/tsan.* 2> /dev/null | grep -c "WARNING: ThreadSanitizer" || true)
{
    echo "tsan_loop.sh: $rounds round(s), $(ls "$out/logs" | wc -l) runs, $reports report(s)"
    if [ "$reports" -gt 0 ]; then
        cat "$out"/reports/tsan.* | awk '
            /WARNING: ThreadSanitizer/ { kind = $0; sub(/.*ThreadSanitizer: /, "", kind); frames = 0; key = kind }
            /^    #[01] / && frames < 4 { f = $0; sub(/^ +#[0-9]+ /, "", f); sub(/ \/.*$/, "", f); key = key " | " f; frames++ }
            /^SUMMARY/ { count[key]++ }
            END { for (k in count) printf "  %dx %s\n", count[k], k }' | sort -rn
    fi
} | tee "$out/summary.txt"
[ "$reports" -eq 0 ] && [ "$failed" -eq 0 ]
