#!/bin/bash
# On a GPU machine, from a copy of the repository holding .gpu/ (demos/gpu/bundle.sh) and .gl/:
# OpenGL through EGL on the GPU (libglvnd unpacked into /, NVIDIA's EGL vendor file), a smoke
# run that must report an NVIDIA renderer, the obscurance cost benchmark, then the styles with
# and without obscurance at 1920x1080 while time is left. Results into $OUT (default /tmp/out).
# env: VO_BUDGET (s, default 270) for the benchmark, STYLE_DEADLINE (s since the start, 400).
set -u
OUT=${OUT:-/tmp/out}
mkdir -p "$OUT"
start=$(date +%s)
cd "$(dirname "$0")/../.."
root=$PWD
for f in .gl/*.deb; do dpkg -x "$f" /; done
ldconfig
for j in /usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json /usr/share/glvnd/egl_vendor.d/10_nvidia.json; do
    if [ -f "$j" ]; then export __EGL_VENDOR_LIBRARY_FILENAMES=$j; break; fi
done
for d in /usr/local/nvidia/lib64 /usr/local/nvidia/lib; do
    [ -d "$d" ] && export LD_LIBRARY_PATH=$d${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
done
export __GL_SYNC_TO_VBLANK=0 SDL_VIDEODRIVER=offscreen SDL_AUDIODRIVER=dummy
nvidia-smi --query-gpu=name,driver_version,clocks.sm,clocks.max.sm --format=csv > "$OUT/gpu.txt" 2>&1
echo "vendor json: ${__EGL_VENDOR_LIBRARY_FILENAMES:-none}; LD_LIBRARY_PATH=${LD_LIBRARY_PATH:-}" >> "$OUT/gpu.txt"
cat "$OUT/gpu.txt"
engine=$root/.gpu/build/bin/nprquake
smoke() {
    rm -rf /tmp/u0; mkdir -p /tmp/u0
    timeout 90 "$engine" -userdir /tmp/u0 -basedir "$root/.gpu/data" -game lq1 -width 640 \
        -height 480 +r_plugin classic +vo_enable 1 +timedemo demo +quit > "$OUT/smoke.log" 2>&1
    echo "smoke rc=$?"; grep -E "GL_|fps|gpu |obscurance off|rror" "$OUT/smoke.log" | head -30
    grep -q "GL_RENDERER: NVIDIA" "$OUT/smoke.log"
}
if ! smoke; then
    echo "--- smoke failed; diagnostics"; tail -25 "$OUT/smoke.log"
    ls -la /usr/local/nvidia/lib64 2>&1 | grep -i -E "egl|libGL" | head
    ls /usr/share/glvnd/egl_vendor.d /usr/local/nvidia/share/glvnd/egl_vendor.d 2>&1
    ldconfig -p | grep -E "libEGL|libGL\.|libOpenGL" | head
    echo "--- retry: explicit EGL library, no vendor override"
    unset __EGL_VENDOR_LIBRARY_FILENAMES
    export SDL_VIDEO_EGL_DRIVER=/usr/lib/x86_64-linux-gnu/libEGL.so.1
    smoke || { tail -25 "$OUT/smoke.log"; exit 1; }
fi
echo "smoke ok after $(( $(date +%s) - start )) s"
BUILD=$root/.gpu/build NPRQ_DATA=$root/.gpu/data PYTHON=python3 timeout "${VO_BUDGET:-270}" \
    bash demos/bench_obscurance.sh --rounds 3 --res "640x480 1024x768" --skip-error \
    --out /tmp/vo > "$OUT/bench.log" 2>&1
echo "bench rc=$? after $(( $(date +%s) - start )) s"
cp /tmp/vo/cost.tsv /tmp/vo/renderer.txt "$OUT/" 2>/dev/null
python3 demos/obscurance_cost.py /tmp/vo/cost.tsv > "$OUT/cost.md" 2>&1; cat "$OUT/cost.md"
# What vo_compute 2's trial measured and chose in each lines5_*fastest run.
grep -H "vo_compute 2" /tmp/vo/logs/*fastest* > "$OUT/trial.txt" 2>&1; cat "$OUT/trial.txt"
# The styles on the GPU, if time is left: classic, technical, illustrative, with and without vo.
styles=/tmp/styles.log; : > $styles
for round in 1 2; do for p in classic technical illustrative; do for vo in 0 1; do
    [ $(( $(date +%s) - start )) -lt "${STYLE_DEADLINE:-400}" ] || break 3
    rm -rf /tmp/u1; mkdir -p /tmp/u1
    echo "== round $round $p vo_enable $vo 1920x1080" >> $styles
    timeout 60 "$engine" -userdir /tmp/u1 -basedir "$root/.gpu/data" -game lq1 -width 1920 \
        -height 1080 +scr_drawhud 0 +vo_enable $vo +vo_mode lines5 +r_plugin $p +timedemo demo \
        +quit 2>&1 | grep -E "fps|frame time|gpu " >> $styles
done; done; done
cp $styles "$OUT/styles.log"; cat $styles
tar czf "$OUT/logs.tgz" -C /tmp/vo logs 2>/dev/null
echo "done after $(( $(date +%s) - start )) s"
