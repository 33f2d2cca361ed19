#!/usr/bin/env bash
# Interleaved timedemo benchmark: our engine (one or more renderer plugins) against QuakeSpasm on
# the same data, demos and resolutions, in the same run. Runs alternate (A, B, A, B, ...) because
# these machines' speed drifts; report ratios, not absolute fps. demos/benchmark.sh runs this,
# then the style gallery and the report with charts.
#
# usage: demos/bench_timedemo.sh [--rounds N] [--plugins "classic technical"] [--demos "demo demo2"]
#                                [--res "640x480 1024x768"] [--no-peer | --peer quakespasm]
#                                [--trace] [--base DIR] [--peer-tail] [--out DIR]
#   --demos   demo names in the game data, or paths of .dem files (e.g. demos/record_gameplay.sh's
#             recordings: copied into the run's user dir; QuakeSpasm gets the same file)
#   --trace   also write every run's per-frame trace (-benchtrace) to DIR/traces/; read them
#             with demos/frame_trace.py
#   --base    another build (its build dir, e.g. of the commit before a change) to run right
#             before each of ours with the same style; its runs are the style "STYLE@base"
#   --peer-tail  time QuakeSpasm with demos/quakespasm_tail.sh, which also logs its every frame
#             (its 99th percentile and 1% low go into the report's tail table)
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release)
# Output: one line per run on stdout with a progress count and an estimate of the time left;
# in --out (default build/bench): results.jsonl (one record per run: fps, the -benchjson record
# with the frame-time percentiles, start-up time, exit status; a run that failed has "failed":
# true and fps null, never a number), frames/ (every run's frame times, -benchframes), logs/
# (every run's output) and summary.md.
set -euo pipefail
source "$(dirname "$0")/common.sh"
rounds=3
plugins="classic"
demos="demo demo2"
resolutions="640x480 1024x768"
peer=1
trace=0
base=""
peer_tail=0
out=$root/build/bench
while [ $# -gt 0 ]; do
    case $1 in
        --rounds) rounds=$2; shift 2 ;;
        --plugins) plugins=$2; shift 2 ;;
        --demos) demos=$2; shift 2 ;;
        --res) resolutions=$2; shift 2 ;;
        --no-peer) peer=0; shift ;;
        --peer) [ "$2" = quakespasm ] && peer=1 || peer=0; shift 2 ;;
        --trace) trace=1; shift ;;
        --base) base=$2; shift 2 ;;
        --peer-tail) peer_tail=1; shift ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
if [ -n "$base" ] && [ ! -x "$base/bin/nprquake" ]; then die "--base $base: no $base/bin/nprquake"; fi
require_data
# The tool installs QuakeSpasm when it runs: the tool is all the peer needs here.
if [ $peer = 1 ] && [ ! -x "$quakespasm_tool" ]; then die "$quakespasm_tool not found; use --no-peer"; fi
mkdir -p "$out/frames" "$out/logs" "$out/user/lq1" "$out/traces"

# A demo given as a file: the engine finds it by name in the user dir.
demo_name() { case $1 in *.dem) basename "$1" .dem ;; *) echo "$1" ;; esac; }
for demo in $demos; do
    case $demo in
        *.dem) [ -f "$demo" ] || die "$demo: no such file"
               cp "$demo" "$out/user/lq1/" ;;
    esac
done
results=$out/results.jsonl
: > "$results"

# A JSON string (or null for an empty value) for the few free-text fields.
json_string() {
    if [ -z "$1" ]; then echo null; return; fi
    printf '"%s"' "$(printf '%s' "$1" | sed 's/\\/\\\\/g; s/"/\\"/g' | tr -d '\000-\037')"
}

run_ours() {  # round plugin demo WxH [engine label]
    local round=$1 plugin=$2 demo res=$4 engine=${5:-$engine} label=${6:-$2}
    demo=$(demo_name "$3")
    local w=${res%x*} h=${res#*x} name="nprquake_${label}_${demo}_${res}_r${round}"
    local trace_args=()
    [ $trace = 1 ] && trace_args=(-benchtrace "$out/traces/$name.tsv")
    local rec=$out/rec.json frames=$out/frames/$name.txt log=$out/logs/$name.log status=0
    rm -f "$rec" "$frames" "$out/traces/$name.tsv"
    SDL_VIDEODRIVER=offscreen "$engine" -userdir "$out/user" -basedir "$data" -game lq1 \
        -width "$w" -height "$h" -window -benchjson "$rec" -benchframes "$frames" \
        -benchmark "$demo" -benchmarkruns 1 "${trace_args[@]}" +r_plugin "$plugin" > "$log" 2>&1 ||
        status=$?
    local line fps startup failure=""
    line=$(grep -E '^[0-9]+ frames' "$log" | tail -1) || true
    fps=$(echo "$line" | awk '{print $5}')
    startup=$(sed -n 's/^start-up to first frame: \([0-9.]*\) s$/\1/p' "$log" | head -1)
    if [ $status != 0 ] || [ -z "$fps" ] || [ ! -s "$rec" ]; then
        failure=$(grep -E 'failed|cannot|error' "$log" | head -1)
        failure=${failure:-exit status $status, no timedemo line}
        fps=""
    fi
    echo "nprquake:$label $demo $res ${fps:-FAILED${failure:+ ($failure)}}"
    printf '{"engine":"nprquake","plugin":"%s","demo":"%s","res":"%s","round":%s,"fps":%s,"failed":%s,"exit_status":%s,"failure":%s,"startup_s":%s,"frames_file":%s,"record":%s}\n' \
        "$label" "$demo" "$res" "$round" "${fps:-null}" "$([ -n "$fps" ] && echo false || echo true)" \
        "$status" "$(json_string "$failure")" "${startup:-null}" \
        "$([ -n "$fps" ] && json_string "frames/$name.txt" || echo null)" \
        "$([ -n "$fps" ] && cat "$rec" || echo null)" >> "$results"
}

run_peer() {  # round demo WxH
    local round=$1 demo res=$3 line fps status=0 tail_json=null
    demo=$(demo_name "$2")
    local log=$out/logs/quakespasm_${demo}_${res}_r$round.log
    if [ $peer_tail = 1 ]; then
        # quakespasm_tail.sh passes the timedemo tool's own line ("quakespasm DEMO WxH FPS") to
        # stderr and prints its frame-time figures on stdout.
        line=$(QUAKESPASM_TIMEDEMO=$quakespasm_tool "$root/demos/quakespasm_tail.sh" "$2" "$res" \
            2>"$log" | tail -1) || status=$?
        tail_json=$(echo "$line" | awk '$1 == "quakespasm-tail" {
            printf "{\"median_ms\":%s,\"p95_ms\":%s,\"p99_ms\":%s,\"low1_fps\":%s,\"avg_fps\":%s}",
                $7, $9, $11, $15, $18 }')
        # Asked for and not measured: the report counts it against the targets.
        tail_json=${tail_json:-'{"failed":true}'}
        line=$(grep -E '^quakespasm ' "$log" | tail -1) || true
    else
        line=$("$quakespasm_tool" "$2" "$res" 1 2>"$log" | tail -1) || status=$?
    fi
    fps=$(echo "$line" | awk '{print $4}')
    case $fps in ''|FAIL|*[!0-9.]*) fps="" ;; esac
    echo "quakespasm $demo $res ${fps:-FAILED}"
    printf '{"engine":"quakespasm","plugin":"","demo":"%s","res":"%s","round":%s,"fps":%s,"failed":%s,"exit_status":%s,"failure":%s,"startup_s":null,"frames_file":null,"record":null,"tail":%s}\n' \
        "$demo" "$res" "$round" "${fps:-null}" "$([ -n "$fps" ] && echo false || echo true)" \
        "$status" "$([ -n "$fps" ] && echo null || json_string "no timedemo line (see logs/)")" \
        "$tail_json" >> "$results"
}

count() { set -- $1; echo $#; }
builds=1
[ -n "$base" ] && builds=2
per_round=$(( $(count "$resolutions") * $(count "$demos") * ($(count "$plugins") * builds + peer) ))
total=$(( rounds * per_round ))
done_runs=0
started=$SECONDS
progress() {  # what ran last
    done_runs=$((done_runs + 1))
    local elapsed=$((SECONDS - started))
    local left=$(( elapsed * (total - done_runs) / done_runs ))
    printf '[%d/%d, %dm%02ds elapsed, ~%dm%02ds left] %s\n' "$done_runs" "$total" \
        $((elapsed / 60)) $((elapsed % 60)) $((left / 60)) $((left % 60)) "$1"
}

for r in $(seq 1 "$rounds"); do
    for res in $resolutions; do
        for demo in $demos; do
            for p in $plugins; do
                if [ -n "$base" ]; then
                    progress "$(run_ours "$r" "$p" "$demo" "$res" "$base/bin/nprquake" "$p@base")"
                fi
                progress "$(run_ours "$r" "$p" "$demo" "$res")"
            done
            if [ $peer = 1 ]; then progress "$(run_peer "$r" "$demo" "$res")"; fi
        done
    done
done
rm -f "$out/rec.json"

/usr/bin/python3 "$root/demos/bench_report.py" --summary-only "$out"
echo "bench_timedemo.sh: results in $results and $out/summary.md"
