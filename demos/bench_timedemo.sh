#!/usr/bin/env bash
# Interleaved timedemo benchmark: our engine (one or more renderer plugins) against QuakeSpasm on
# the same data, demos and resolutions, in the same run. Runs alternate (A, B, A, B, ...) because
# these machines' speed drifts; report ratios, not absolute fps.
#
# usage: demos/bench_timedemo.sh [--rounds N] [--plugins "classic technical"] [--demos "demo demo2"]
#                                [--res "640x480 1024x768"] [--no-peer] [--out DIR]
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Output: one line per run on stdout, a JSON Lines file and a Markdown summary in --out
# (default build/bench), each run's -benchjson record included.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
data=${NPRQ_DATA:-$root/../shared/data}
build=${BUILD:-$root/build/release}
rounds=3
plugins="classic"
demos="demo demo2"
resolutions="640x480 1024x768"
peer=1
out=$root/build/bench
while [ $# -gt 0 ]; do
    case $1 in
        --rounds) rounds=$2; shift 2 ;;
        --plugins) plugins=$2; shift 2 ;;
        --demos) demos=$2; shift 2 ;;
        --res) resolutions=$2; shift 2 ;;
        --no-peer) peer=0; shift ;;
        --out) out=$2; shift 2 ;;
        *) echo "bench_timedemo.sh: unknown option $1" >&2; exit 2 ;;
    esac
done
engine=$build/bin/nprquake
[ -x "$engine" ] || { echo "bench_timedemo.sh: build first ($engine missing)" >&2; exit 1; }
[ -d "$data/lq1" ] || { echo "bench_timedemo.sh: no game data at $data/lq1" >&2; exit 1; }
peer_script=$root/../shared/tools/quakespasm_timedemo.sh
if [ $peer = 1 ] && [ ! -x "$peer_script" ]; then
    echo "bench_timedemo.sh: $peer_script not found; use --no-peer" >&2; exit 1
fi
mkdir -p "$out"
results=$out/results.jsonl
: > "$results"

run_ours() {  # plugin demo WxH
    local w=${3%x*} h=${3#*x} rec=$out/rec.json line
    rm -f "$rec"
    line=$(SDL_VIDEODRIVER=offscreen "$engine" -basedir "$data" -game lq1 -width "$w" -height "$h" \
        -window -benchjson "$rec" +r_plugin "$1" +timedemo "$2" +quit 2>&1 |
        grep -E '^[0-9]+ frames' | tail -1) || true
    local fps; fps=$(echo "$line" | awk '{print $5}')
    echo "nprquake:$1 $2 $3 ${fps:-FAIL}"
    printf '{"engine":"nprquake","plugin":"%s","demo":"%s","res":"%s","fps":%s,"record":%s}\n' \
        "$1" "$2" "$3" "${fps:-null}" "$(cat "$rec" 2>/dev/null || echo null)" >> "$results"
}

run_peer() {  # demo WxH
    local line fps
    line=$("$peer_script" "$1" "$2" 1 2>/dev/null | tail -1)
    fps=$(echo "$line" | awk '{print $4}')
    [ "$fps" = FAIL ] && fps=""
    echo "quakespasm $1 $2 ${fps:-FAIL}"
    printf '{"engine":"quakespasm","plugin":"","demo":"%s","res":"%s","fps":%s}\n' \
        "$1" "$2" "${fps:-null}" >> "$results"
}

for r in $(seq 1 "$rounds"); do
    for res in $resolutions; do
        for demo in $demos; do
            for p in $plugins; do run_ours "$p" "$demo" "$res"; done
            [ $peer = 1 ] && run_peer "$demo" "$res"
        done
    done
done

python3 - "$results" "$out/summary.md" <<'PY'
import json, statistics, sys
rows = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
groups = {}
for r in rows:
    key = (r["demo"], r["res"])
    name = r["engine"] + (":" + r["plugin"] if r["plugin"] else "")
    if r["fps"] is not None:
        groups.setdefault(key, {}).setdefault(name, []).append(r["fps"])
lines = ["| demo | resolution | engine | runs | median fps | ratio vs quakespasm | ratio vs classic |",
         "|---|---|---|---|---|---|---|"]
for (demo, res), engines in sorted(groups.items()):
    peer = statistics.median(engines["quakespasm"]) if "quakespasm" in engines else None
    classic = statistics.median(engines["nprquake:classic"]) if "nprquake:classic" in engines else None
    for name, fps in sorted(engines.items()):
        med = statistics.median(fps)
        ratio = "%.2fx" % (med / peer) if peer else "-"
        vs_classic = "%.2fx" % (med / classic) if classic and name.startswith("nprquake:") else "-"
        lines.append("| %s | %s | %s | %d | %.1f | %s | %s |" % (demo, res, name, len(fps), med, ratio, vs_classic))
open(sys.argv[2], "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
echo "bench_timedemo.sh: results in $results and $out/summary.md"
