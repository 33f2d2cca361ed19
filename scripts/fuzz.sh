#!/usr/bin/env bash
# Fuzz one format: fuzz.sh [--bin-dir DIR] FORMAT SECONDS [extra fuzzer args...]
#   FORMAT is the suffix of a fuzz target (pak, wad, bsp, mdl, spr, dem, progs, sav, wav,
#   material, warp_ramp, vo_scene).
#   Seeds: synthetic files written by the target itself (-nq_write_seeds) plus real files of
#   that format from the game data ($NPRQ_DATA, default ../shared/data), copied into a
#   corpus folder under the build tree, never into the repository.
# The default bin dir is build/fuzz/fuzz (the libFuzzer build from `cmake --preset fuzz`).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
bin_dir=$root/build/fuzz/fuzz
if [ "${1:-}" = "--bin-dir" ]; then bin_dir=$2; shift 2; fi
format=${1:?usage: fuzz.sh [--bin-dir DIR] FORMAT SECONDS [args...]}
seconds=${2:?usage: fuzz.sh [--bin-dir DIR] FORMAT SECONDS [args...]}
shift 2
target=$bin_dir/fuzz_$format
[ -x "$target" ] || { echo "fuzz.sh: no fuzz target $target (build it first)" >&2; exit 1; }
data=${NPRQ_DATA:-$root/../shared/data}
[ -d "$data" ] || { echo "fuzz.sh: game data not found at $data (set NPRQ_DATA)" >&2; exit 1; }

case $format in
    pak) exts="pak" ;;
    wad) exts="wad lmp" ;;
    bsp) exts="bsp" ;;
    mdl) exts="mdl" ;;
    spr) exts="spr" ;;
    dem|client) exts="dem" ;;
    progs) exts="dat" ;;
    sav) exts="sav" ;;
    wav) exts="wav" ;;
    warp_ramp) exts="lmp png" ;;
    material) exts="mat" ;;
    host) exts="cfg rc" ;;  # default.cfg, quake.rc: the console language as games write it
    *) exts="" ;;
esac

work=$bin_dir/corpus/$format
seeds=$bin_dir/seeds/$format
mkdir -p "$work" "$seeds"
"$target" -nq_write_seeds="$seeds" >/dev/null
for e in $exts; do
    # Small real files make fast seeds; the biggest ones slow every execution down.
    find "$data" -type f -iname "*.$e" -size -700k -exec cp -f {} "$seeds/" \;
done
echo "fuzz.sh: $format: $(ls "$seeds" | wc -l) seed files, $seconds s"
exec "$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 "$@" "$work" "$seeds"
