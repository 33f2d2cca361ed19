#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build the release preset, then run a
# headless timedemo of demo.dem on the game data in ../shared/data (or $NPRQ_DATA) with the
# `classic` renderer. Without game data it shows the built-in showroom and saves a screenshot.
# Extra arguments go to nprquake (e.g. +r_plugin null, -width 1024 -height 768).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
# The engine, the renderer plugins and the tools; the tests are scripts/test.sh's build.
cmake --build --preset release -j "$(nproc)" --target programs
data=${NPRQ_DATA:-../shared/data}
export SDL_VIDEODRIVER=${SDL_VIDEODRIVER:-offscreen}
engine=build/release/bin/nprquake
userdir=build/release/user
# 640x480 unless the caller chose a size (the game's default.cfg asks vid_restart for 1280x720).
size=(-width 640 -height 480)
for arg in "$@"; do [[ "${arg,,}" == -width || "${arg,,}" == -height ]] && size=(); done
if [ -d "$data/lq1" ]; then
    exec "$engine" -userdir "$userdir" -basedir "$data" -game lq1 "${size[@]}" "$@" +timedemo demo +quit
fi
echo "main.sh: no game data at $data/lq1 (set NPRQ_DATA): showing the built-in showroom" >&2
exec "$engine" -userdir "$userdir" -basedir "$data" "$@" \
    +wait +wait +wait +screenshot build/release/showroom.png +quit
