#!/usr/bin/env bash
# The game's own costs, headless:
#   0. serverbench: the server alone on e2m3 with its monsters woken (until half hunt, as many as a player can meet) and hunting the
#      god-mode player, 60 s of server frames (median, 95th, 99th percentile, worst);
# and scripted sessions of ordinary console commands in the engine:
#   1. server frame time in the engine (`serverprofile`) while the player flies through e2m3
#      (noclip, god) firing rockets: the same server work, sharing the CPU with rendering;
#   2. level load: `map e2m3` to its first drawn frame with `classic` (median of the runs);
#   3. playing lq1m1 against a timedemo of a recording of the same session: the game's host
#      frames (`gamestats`) and the timedemo's, interleaved (play, replay, play, replay...).
# Every session runs at host_framerate 1/72: one server frame per host frame, as a timedemo reads
# one block per frame.
#
# usage: demos/bench_game.sh [--runs N] [--res WxH] [--out DIR]
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=2,14
runs=3
res=640x480
out=$root/build/bench_game
while [ $# -gt 0 ]; do
    case $1 in
        --runs) runs=$2; shift 2 ;;
        --res) res=$2; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
require_data
user=$out/user
mkdir -p "$user/lq1"
w=${res%x*}
h=${res#*x}

waits() { for _ in $(seq "$1"); do echo wait; done; }

# e2m3: fly through the level with rockets; monsters wake and hunt.
{
    echo "host_framerate 0.0138889"; echo "host_maxfps 0"; echo "map e2m3"; waits 10
    echo "god"; echo "noclip"; echo "impulse 9"; echo "impulse 7"; waits 5
    echo "serverprofile clear"
    for leg in 1 2 3 4 5 6; do
        echo "+forward"; echo "+attack"; waits 360; echo "-attack"; echo "-forward"
        echo "+right"; waits $((20 + leg * 7)); echo "-right"
    done
    echo "status"; echo "serverprofile"; echo "quit"
} > "$user/lq1/bench_e2m3.cfg"

# lq1m1: walk, turn and fire, recorded.
{
    echo "host_framerate 0.0138889"; echo "host_maxfps 0"; echo "record bench_lq1m1 lq1m1"; waits 10
    echo "god"; echo "impulse 9"; echo "gamestats"
    for leg in 1 2 3 4 5; do
        echo "+forward"; echo "+attack"; waits 200; echo "-attack"; echo "-forward"
        echo "+left"; waits $((30 + leg * 11)); echo "-left"
    done
    echo "gamestats"; echo "stop"; echo "quit"
} > "$user/lq1/bench_lq1m1.cfg"

run() {  # args...
    SDL_VIDEODRIVER=offscreen "$engine" -basedir "$data" -game lq1 -userdir "$user" \
        -width "$w" -height "$h" -window "$@" 2>&1
}

summary=$out/summary.md
{
    echo "# bench_game.sh $(date -u +%Y-%m-%dT%H:%MZ), $res, $runs runs"
    echo
} > "$summary"

echo "== serverbench e2m3 / lq1m1: the server alone, monsters hunting"
for map in e2m3 lq1m1; do
    for i in $(seq "$runs"); do
        line=$("$build/bin/serverbench" -basedir "$data" -game lq1 --map "$map" --hunting 0.5 --seconds 60 2>&1) ||
            line="serverbench $map: FAILED: $line"
        echo "$line"
        echo "- $line" >> "$summary"
    done
done

echo "== e2m3 in the engine: server frame time while flying through the level"
for i in $(seq "$runs"); do
    log=$(run +exec bench_e2m3.cfg)
    prof=$(echo "$log" | grep '^server frames:' | tail -1)
    [ -n "$prof" ] || prof="FAILED (no serverprofile line)"
    hunting=$(echo "$log" | grep -o '[0-9]* hunting the player' | tail -1)
    load=$(echo "$log" | grep -o 'first frame [0-9]* ms' | head -1)
    echo "run $i: $prof; $hunting; map e2m3 $load"
    echo "- e2m3 run $i: $prof; $hunting; $load" >> "$summary"
done

echo "== lq1m1: playing vs a timedemo of the recording (interleaved)"
for i in $(seq "$runs"); do
    log=$(run +exec bench_lq1m1.cfg)
    play=$(echo "$log" | grep '^game: ' | tail -1)
    demo=$(run +timedemo bench_lq1m1 +quit | grep -E '^[0-9]+ frames' | tail -1)
    p_fps=$(echo "$play" | awk '{print $6}')
    d_fps=$(echo "$demo" | awk '{print $5}')
    # A ratio only when both runs really happened.
    ratio=$(awk -v p="${p_fps:-0}" -v d="${d_fps:-0}" 'BEGIN { if (p > 0 && d > 0) printf "%.3f", d / p; else print "FAILED" }')
    [ -n "$play" ] || play="game: FAILED (no gamestats line)"
    [ -n "$demo" ] || demo="FAILED (no timedemo line)"
    echo "run $i: playing: ${play#game: }; timedemo: $demo; play/timedemo frame time: $ratio"
    echo "- lq1m1 run $i: playing ${play#game: }; timedemo $demo; play/timedemo frame time $ratio" >> "$summary"
done
echo "summary: $summary"
