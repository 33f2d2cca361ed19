#!/usr/bin/env bash
# What the technical style pays to register alias models (bin/bench_technical_models): the time
# of AliasEdgeMesh::create (adjacency recovery and the edge data it keeps; the best of --repeat
# runs per model), the heap it keeps per model and the peak heap above that while it builds,
# summed over every .mdl of the data's progs/. With --base, another build's program runs before
# ours in every round (A, B, A, B: the machine's speed drifts), and the ratios are printed.
#
# usage: demos/bench_technical_models.sh [--rounds N] [--repeat N] [--base DIR] [--out DIR]
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=8,9
rounds=3
repeat=5
base=""
out=""
while [ $# -gt 0 ]; do
    case $1 in
        --rounds) rounds=$2; shift 2 ;;
        --repeat) repeat=$2; shift 2 ;;
        --base) base=$2; shift 2 ;;
        -h | --help) usage; exit 0 ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build bench_technical_models
require_data
if [ -n "$base" ] && [ ! -x "$base/bin/bench_technical_models" ]; then
    die "--base $base: no $base/bin/bench_technical_models (build its bench_technical_models target)"
fi
out=${out:-$build/bench_technical_models}
mkdir -p "$out"
results=$out/results.txt
: > "$results"
for ((r = 1; r <= rounds; r++)); do
    for which in base ours; do
        case $which in
            base) [ -n "$base" ] || continue; program=$base/bin/bench_technical_models ;;
            ours) program=$build/bin/bench_technical_models ;;
        esac
        line=$("$program" --repeat "$repeat" "$data/lq1/progs" > "$out/${which}_$r.txt" &&
            tail -1 "$out/${which}_$r.txt")
        echo "$which round $r: ${line#total }" | tee -a "$results"
    done
done
# Per build: the median create time over the rounds; kept and peak heap do not vary by round.
awk '{ b = $1; rounds[b]++
       for (i = 4; i <= NF; i++) { split($i, kv, "="); v[b, kv[1], rounds[b]] = kv[2] } }
     END {
       for (b in rounds) {
         m = rounds[b]
         for (i = 1; i <= m; i++) t[i] = v[b, "create_ms", i]
         for (i = 2; i <= m; i++) for (j = i; j > 1 && t[j - 1] > t[j]; j--) { x = t[j]; t[j] = t[j - 1]; t[j - 1] = x }
         median[b] = (m % 2) ? t[(m + 1) / 2] : (t[m / 2] + t[m / 2 + 1]) / 2
         printf "%s: %d models, create %.1f ms (median of %d rounds), kept %.1f KiB, peak %.1f KiB\n",
                b, v[b, "models", 1], median[b], m, v[b, "kept_kib", 1], v[b, "peak_kib", 1]
       }
       if (("base" in rounds) && ("ours" in rounds))
         printf "ours / base: create %.2fx, kept %.2fx, peak %.2fx\n", median["ours"] / median["base"],
                v["ours", "kept_kib", 1] / v["base", "kept_kib", 1], v["ours", "peak_kib", 1] / v["base", "peak_kib", 1]
     }' "$results" | sort | tee "$out/summary.txt"
