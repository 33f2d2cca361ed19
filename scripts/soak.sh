#!/usr/bin/env bash
# Soak run under AddressSanitizer + LeakSanitizer: one engine process plays, for --minutes of
# game time, cycles of the demo loop and a scripted game (fire, walk into pick-ups, save and
# load, a changelevel and back, a style swap in every style) with the frame step fixed
# (host_framerate), while this script samples its resident memory. It passes when the process
# ends by itself with status 0, no sanitizer report and no error line, and resident memory
# over the last third of the cycles is less than --growth percent above the first third's.
#
# usage: scripts/soak.sh [--minutes N] [--step SECONDS] [--growth PERCENT] [--out DIR]
#   --minutes  game time to play (default 30)
#   --step     host_framerate: game seconds per frame (default 0.05)
#   --growth   largest growth of peak resident memory from the first third of the cycles to the
#              last, in percent (default 1; 10 for an ASan build, whose allocator keeps freed
#              memory in its quarantine and pools: +5% over 30 cycles where a release build
#              stays flat, docs/soundness.md)
#   --out      logs and the memory samples (default build/asan/soak)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/asan: scripts/test.sh's build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
data=${NPRQ_DATA:-$root/../shared/data}
build=${BUILD:-$root/build/asan}
minutes=30
step=0.05
growth=
out=$build/soak
while [ $# -gt 0 ]; do
    case $1 in
        --minutes) minutes=$2; shift 2 ;;
        --step) step=$2; shift 2 ;;
        --growth) growth=$2; shift 2 ;;
        --out) out=$2; shift 2 ;;
        *) sed -n '9,17p' "$0" >&2; exit 2 ;;
    esac
done
engine=$build/bin/nprquake
[ -x "$engine" ] || { echo "soak.sh: $engine not built (bash scripts/test.sh builds it)" >&2; exit 1; }
[ -d "$data/lq1" ] || { echo "soak.sh: no game data at $data/lq1 (set NPRQ_DATA)" >&2; exit 1; }
rm -rf "$out"
mkdir -p "$out/user/lq1"

# One cycle is 60 s of game time: 20 s of the demo loop, then 40 s of a game.
frames_per_second=$(awk -v s="$step" 'BEGIN { printf "%d", 1 / s + 0.5 }')
cycles=$minutes
{
    # w1 .. w1000: that many frames of waiting (Quake's wait defers the rest by one frame).
    echo 'alias w1 "wait"'
    echo 'alias w10 "w1;w1;w1;w1;w1;w1;w1;w1;w1;w1"'
    echo 'alias w100 "w10;w10;w10;w10;w10;w10;w10;w10;w10;w10"'
    echo "alias sec \"$(for ((i = 0; i < frames_per_second; i++)); do printf 'w1;'; done)\""
    echo 'alias sec5 "sec;sec;sec;sec;sec"'
    echo 'alias demo_part "startdemos demo demo2; sec5; sec5; sec5; sec5"'
    # Fire, walk (LibreQuake's start room has pick-ups along the way), turn, switch weapons.
    echo 'alias play "+attack; sec; -attack; +forward; sec; sec; -forward; +right; sec; -right; impulse 2; +attack; sec; -attack; +back; sec; -back"'
    echo 'alias game_part "map start; sec; play; save soak; sec; load soak; sec; r_plugin technical; play; r_plugin illustrative; vo_enable 1; play; vo_enable 0; changelevel e2m3; sec; play; r_plugin classic; changelevel start; sec; play; sec"'
    echo 'alias cycle "demo_part; game_part; echo soak: cycle done"'
    for ((c = 0; c < cycles; c++)); do echo cycle; done
    echo 'echo soak: done'
    echo quit
} > "$out/user/lq1/soak.cfg"

# The engine as the tests run it under ASan (tests/support/engine_run.cpp): the Mesa driver
# preloaded so that LeakSanitizer scans its globals instead of reporting them at unload.
# A build without ASan (BUILD=build/release: memory figures without the sanitizer's quarantine
# and pools) runs as it is.
preload=""
case $(ldd "$engine") in *libasan*) asan_build=1 ;; *) asan_build=0 ;; esac
[ -n "$growth" ] || { [ "$asan_build" = 1 ] && growth=10 || growth=1; }
if [ "$asan_build" = 1 ]; then
    if asan=$(gcc -print-file-name=libasan.so) && [ -f "$asan" ]; then preload=$asan; fi
    driver=$(ls /usr/lib/*/dri/swrast_dri.so 2> /dev/null | head -1 || true)
    [ -n "$driver" ] && preload="${preload:+$preload:}$driver"
fi
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:quarantine_size_mb=16}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy

start=$(date +%s)
LD_PRELOAD=$preload "$engine" -userdir "$out/user" -basedir "$data" -game lq1 -width 320 \
    -height 240 -window +host_framerate "$step" +exec soak.cfg > "$out/engine.log" 2>&1 &
pid=$!
echo "seconds cycles_done rss_kb" > "$out/memory.txt"
while kill -0 "$pid" 2> /dev/null; do
    rss=$(awk '/^VmRSS/ { print $2 }' "/proc/$pid/status" 2> /dev/null || true)
    done_cycles=$(grep -c "soak: cycle done" "$out/engine.log" || true)
    [ -n "$rss" ] && echo "$(($(date +%s) - start)) $done_cycles $rss" >> "$out/memory.txt"
    sleep 5
done
status=0
wait "$pid" || status=$?

# Memory: a leak grows resident memory cycle after cycle, while the allocator's pools (larger
# under ASan, whose quarantine holds freed blocks back) fill during the first cycles and then
# stay. So the peak over the last third of the cycles is compared with the peak over the first
# third after the first cycle (levels, styles and sounds all loaded once).
read -r base peak last <<< "$(awk -v n="$cycles" 'NR > 1 && $2 >= 1 {
        third = (n >= 3) ? int(n / 3) : 1
        if ($2 <= third && $3 > b) b = $3
        if ($2 >= n - third && $3 > p) p = $3
        l = $3 }
    END { print b + 0, p + 0, l + 0 }' "$out/memory.txt")"
reports=$(grep -cE "ERROR: (Address|Leak)Sanitizer|runtime error:" "$out/engine.log" || true)
errors=$(grep -cE "^(SERVER )?ERROR|^cannot load level" "$out/engine.log" || true)
cycles_done=$(grep -c "soak: cycle done" "$out/engine.log" || true)
growth_pct=$(awk -v b="$base" -v l="$last" -v p="$peak" 'BEGIN { if (b > 0) printf "%.2f", 100 * (p - b) / b; else print "nan" }')
{
    echo "soak.sh: $cycles_done of $cycles cycles ($minutes min of game time at host_framerate $step) in $(($(date +%s) - start)) s, exit status $status"
    echo "soak.sh: resident memory: peak over the first third of the cycles $((base / 1024)) MiB, over the last third $((peak / 1024)) MiB, last sample $((last / 1024)) MiB: growth $growth_pct% (limit $growth%)"
    echo "soak.sh: $reports sanitizer report(s), $errors error line(s) (log: $out/engine.log)"
} | tee "$out/summary.txt"
[ "$status" = 0 ] && [ "$reports" = 0 ] && [ "$errors" = 0 ] && [ "$cycles_done" = "$cycles" ] &&
    awk -v g="$growth_pct" -v limit="$growth" 'BEGIN { exit !(g != "nan" && g < limit) }'
