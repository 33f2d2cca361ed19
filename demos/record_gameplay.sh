#!/usr/bin/env bash
# Records gameplay demos for the frame-time benchmarks: our engine plays each map headless from a
# script of ordinary console commands (skill 1, god mode, walking, strafing, turning and firing
# the super nailgun, the grenade launcher and the rocket launcher in turn), recording what the
# client receives. host_framerate 1/72 and a fixed sv_seed make every run record the same demo,
# byte for byte; QuakeSpasm plays the files too (protocol 666).
#
# usage: demos/record_gameplay.sh [--maps "e2m3 lq1m1"] [--legs N] [--out DIR]
#   --legs N   fire-and-turn legs per map, about 4.6 s each (default 8: ~37 s, ~2,700 frames)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Writes DIR/play_<map>.dem (default DIR: build/gameplay) and prints one line per demo.
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=2,11
maps="e2m3 lq1m1"
legs=8
out=$root/build/gameplay
while [ $# -gt 0 ]; do
    case $1 in
        --maps) maps=$2; shift 2 ;;
        --legs) legs=$2; shift 2 ;;
        -h|--help) usage; exit 0 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
require_data
user=$(mktemp -d)
trap 'rm -rf "$user"' EXIT
mkdir -p "$user/lq1" "$out"

waits() { for _ in $(seq "$1"); do echo wait; done; }
weapon() {  # the leg's weapon: super nailgun, grenade launcher, rocket launcher
    case $(($1 % 3)) in 1) echo "impulse 5" ;; 2) echo "impulse 6" ;; 0) echo "impulse 7" ;; esac
}

for map in $maps; do
    {
        echo "host_framerate 0.0138889"; echo "host_maxfps 0"; echo "sv_seed 1"; echo "skill 1"
        echo "record play_$map $map"; waits 10
        # give, not impulse 9: a mod's QuakeC may leave that cheat out (LibreQuake's does).
        echo "god"; echo "give 5"; echo "give 6"; echo "give 7"; echo "give n 200"; echo "give r 100"
        for leg in $(seq "$legs"); do
            weapon "$leg"
            echo "+forward"; echo "+attack"; waits 250; echo "-attack"
            echo "+moveleft"; waits 40; echo "-moveleft"; echo "-forward"
            echo "+right"; waits $((25 + leg * 9)); echo "-right"
        done
        echo "stop"; echo "quit"
    } > "$user/lq1/play_$map.cfg"
    SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy "$engine" -basedir "$data" -game lq1 \
        -userdir "$user" -width 320 -height 240 -window +r_plugin null +exec "play_$map.cfg" \
        > "$user/play_$map.log" 2>&1 || { cat "$user/play_$map.log" >&2; exit 1; }
    [ -s "$user/lq1/play_$map.dem" ] || {
        echo "record_gameplay.sh: $map: no demo recorded" >&2; tail -5 "$user/play_$map.log" >&2; exit 1; }
    cp "$user/lq1/play_$map.dem" "$out/"
    echo "$out/play_$map.dem $(stat -c %s "$out/play_$map.dem") bytes"
done
