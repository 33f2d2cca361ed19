#!/usr/bin/env bash
# Volumetric obscurance: what each vo_mode costs and how far it is from the converged reference.
#
#   cost   timedemo of demo.dem under `classic`, obscurance off and every mode (lines5, lines9,
#          points12, points33, area1, lines5 at half resolution: all as compute shaders;
#          lines5 at full and at half resolution drawn over full-screen triangles, and with
#          each stage the way a trial measures faster, vo_compute 2, the default), runs
#          interleaved (off, lines5, ..., then the next resolution, then the next round): fps,
#          and the obscurance pass's GPU time per stage from the engine's timer queries
#          (timedemo's "gpu obscurance" and "gpu vo_*" lines: moments, estimate, blur,
#          composite).
#   error  the same paused demo.dem frames with `vo_show 1` in every mode (the sampled ones also
#          with Poisson-disk and Lloyd sets, vo_sample_set; turned per pixel only, as the paper,
#          vo_shift 0; and electrostatic sets of the neighbouring counts, vo_sample_count) and
#          in `reference` (64 x 64 stratified lines, not randomised or blurred), then a stretch
#          of consecutive frames for flicker; at the stills the frame's geometry too
#          (vo_dump_scene), ray-traced by vo_reference (Embree); demos/obscurance_error.py
#          computes RMSE and SSIM against both references, and flicker.
#
# usage: demos/bench_obscurance.sh [--res "640x480 1024x768"] [--rounds N] [--skip-cost]
#                                  [--skip-error] [--out DIR]  (default build/bench_obscurance)
# Output in DIR: cost.tsv (round, resolution, config, fps, the pass's GPU ms/frame in all and
# per stage), cost.md (medians over the rounds, ratios to off and to points12), error.md (the error
# table), error_frame_N.jpg (lines5, points12, area1, reference, raytraced side by side), shots/,
# scenes/, logs/.
# env:   NPRQ_DATA (default ../shared/data), BUILD (default build/release), PYTHON (default
#        /usr/bin/python3)
# Every run starts from its own empty user dir with every vo_* cvar on the command line, so
# an archived config cannot leak in.
set -euo pipefail
source "$(dirname "$0")/common.sh"
python=${PYTHON:-/usr/bin/python3}  # with numpy and PIL, for the error table
resolutions="640x480 1024x768"
out=$root/build/bench_obscurance
cost=1
error=1
rounds=1
while [ $# -gt 0 ]; do
    case $1 in
        --res) resolutions=$2; shift 2 ;;
        --rounds) rounds=$2; shift 2 ;;
        --skip-cost) cost=0; shift ;;
        --skip-error) error=0; shift ;;
        *) common_option "$@"; shift "$common_shift" ;;
    esac
done
require_build
require_data
mkdir -p "$out/logs" "$out/shots" "$out/scenes"
defaults="+vo_radius 24 +vo_radius2 0 +vo_dual_min 0 +vo_thickness 32 +vo_strength 1 \
+vo_normal 1 +vo_show 0 +vo_compute 1 +vo_shift 1"

run_engine() {  # width height log args...
    local width=$1 height=$2 log=$3 user
    shift 3
    user=$(mktemp -d)
    SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy "$engine" -userdir "$user" -basedir "$data" \
        -game lq1 -width "$width" -height "$height" +con_notifytime 0 +scr_drawhud 0 \
        +gl_polyblend 0 $defaults "$@" > "$log" 2>&1 || true
    rm -rf "$user"
}

configs=(
    "off|+vo_enable 0"
    "lines5|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 0"
    "lines9|+vo_enable 1 +vo_mode lines9 +vo_blur 1 +vo_half 0"
    "points12|+vo_enable 1 +vo_mode points12 +vo_blur 1 +vo_half 0"
    "points33|+vo_enable 1 +vo_mode points33 +vo_blur 1 +vo_half 0"
    "area1|+vo_enable 1 +vo_mode area1 +vo_blur 1 +vo_half 0"
    "lines5_half|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 1"
    "lines5_fragment|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 0 +vo_compute 0"
    "lines5_half_fragment|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 1 +vo_compute 0"
    "lines5_fastest|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 0 +vo_compute 2"
    "lines5_half_fastest|+vo_enable 1 +vo_mode lines5 +vo_blur 1 +vo_half 1 +vo_compute 2"
)

if [ "$cost" = 1 ]; then
    # Rounds interleave everything (round 1: every config at every resolution, then round 2),
    # so a machine's drift reaches every config alike.
    printf 'round\tresolution\tconfig\tfps\tobscurance_ms\tmoments_ms\testimate_ms\tblur_ms\tcomposite_ms\n' \
        > "$out/cost.tsv"
    for round in $(seq "$rounds"); do
        for res in $resolutions; do
            for entry in "${configs[@]}"; do
                name=${entry%%|*}
                log=$out/logs/cost_${name}_${res}_$round.log
                # shellcheck disable=SC2086
                run_engine "${res%x*}" "${res#*x}" "$log" ${entry#*|} +r_plugin classic \
                    +timedemo demo +quit
                grep -m1 "GL_RENDERER" "$log" > "$out/renderer.txt" || true
                fps=$(awk '/frames .* seconds .* fps/ {print $5}' "$log" | tail -1)
                # Per stage (exclusive times): the whole pass is their sum.
                stages=$(awk '/^ *gpu (obscurance|vo_)/ {t[$2] = $3}
                    END {
                        total = t["obscurance"] + t["vo_moments"] + t["vo_estimate"] + \
                                t["vo_blur"] + t["vo_composite"]
                        if ("vo_estimate" in t)
                            printf "%.4f\t%.4f\t%.4f\t%.4f\t%.4f", total, t["vo_moments"],
                                   t["vo_estimate"], t["vo_blur"],
                                   t["vo_composite"] + t["obscurance"]
                    }' "$log")
                # A pass that did not build leaves the frame rate of a run without it: no number.
                if grep -q "obscurance off" "$log" || { [ "$name" != off ] && [ -z "$stages" ]; }; then
                    fps=""
                    stages="failed"
                fi
                [ "$name" = off ] && stages=$(printf '0\t0\t0\t0\t0')
                printf '%s\t%s\t%s\t%s\t%s\n' "$round" "$res" "$name" "${fps:-failed}" "$stages" |
                    tee -a "$out/cost.tsv"
            done
        done
    done
    "$python" "$root/demos/obscurance_cost.py" "$out/cost.tsv" | tee "$out/cost.md"
fi

if [ "$error" = 1 ]; then
    # name|commands: every mode with the paper's electrostatic sets, the sampled modes with
    # plain Poisson-disk and Lloyd-relaxed sets too, and the reference last.
    shots=()
    for m in lines5 lines9 points12 points33 area1; do
        shots+=("$m|vo_mode $m; vo_sample_set electrostatic; vo_sample_count 0")
    done
    # The paper's per-pixel pattern: the set turned (and mirrored), not shifted (vo_shift 0;
    # every shot starts from vo_shift 1, the default).
    for m in lines5 lines9 points12 points33; do
        shots+=("${m}_turned|vo_mode $m; vo_sample_set electrostatic; vo_sample_count 0; vo_shift 0")
    done
    for m in lines5 lines9 points12 points33; do
        for set in poisson lloyd; do
            shots+=("${m}_$set|vo_mode $m; vo_sample_set $set; vo_sample_count 0")
        done
    done
    # The paper's counts' neighbours (electrostatic sets).
    for n in 4 6 8 10; do
        shots+=("lines$n|vo_mode lines5; vo_sample_set electrostatic; vo_sample_count $n")
    done
    for n in 11 13 32 34; do
        shots+=("points$n|vo_mode points12; vo_sample_set electrostatic; vo_sample_count $n")
    done
    shots+=("reference|vo_mode reference; vo_sample_count 0")
    stills="300 760 1200"
    stretch=$(seq 700 709)
    frame_commands() {  # frame -> the commands that shoot every configuration there
        local f=$1 entry commands="pause 1; vo_enable 1; vo_show 1"
        for entry in "${shots[@]}"; do
            commands+="; vo_shift 1; ${entry#*|}; wait; wait; screenshot $out/shots/${entry%%|*}_$f.png"
        done
        # The geometry of a still, for the ray-traced reference (written at the next frame drawn).
        case " $stills " in *" $f "*) commands+="; vo_dump_scene $out/scenes/$f.bin; wait; wait" ;; esac
        echo "$commands; vo_enable 0; pause 0"  # the frames between play without it
    }
    user=$(mktemp -d)
    mkdir -p "$user/lq1"
    for f in $stills $stretch; do echo "demo_at $f \"$(frame_commands "$f")\""; done \
        > "$user/lq1/frames.cfg"
    last=$(printf '%s\n' $stills $stretch | sort -n | tail -1)
    echo "demo_at $((last + 1)) quit" >> "$user/lq1/frames.cfg"
    SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy "$engine" -userdir "$user" -basedir "$data" \
        -game lq1 -width 640 -height 480 +con_notifytime 0 +scr_drawhud 0 +gl_polyblend 0 \
        $defaults +vo_enable 0 +vo_blur 1 +vo_half 0 +r_drawviewmodel 0 +r_plugin classic \
        +exec frames.cfg \
        +timedemo demo > "$out/logs/error.log" 2>&1 || true
    rm -rf "$user"
    for f in $stills; do
        "$build/bin/vo_reference" "$out/scenes/$f.bin" "$out/shots/raytraced_$f.png" --radius 24 \
            >> "$out/logs/vo_reference.log" 2>&1
    done
    names=$(for entry in "${shots[@]}"; do echo "${entry%%|*}"; done)
    "$python" "$root/demos/obscurance_error.py" --shots "$out/shots" \
        --configs "$(echo $names)" --stills "$stills" --stretch "$(echo $stretch)" \
        --sheets "$out" | tee "$out/error.md"
fi
echo "bench_obscurance.sh: results in $out"
