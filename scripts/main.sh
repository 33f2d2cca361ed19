#!/usr/bin/env bash
# The main job on a fresh machine: install dependencies, build the release preset, and run it on
# the game data in ../shared/data (or $NPRQ_DATA).
# Until the engine lands this is the inspection tools over the bundled data.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake --preset release
cmake --build --preset release -j "$(nproc)"
data=${NPRQ_DATA:-../shared/data}
bin=build/release/bin
if [ ! -d "$data/lq1" ]; then
    echo "main.sh: no game data at $data/lq1 (set NPRQ_DATA); nothing to inspect" >&2
    exit 1
fi
"$bin/demotool" info "$data/lq1/demo.dem"
"$bin/mdltool" info "$data/lq1/progs"
