#!/usr/bin/env bash
# Installs every build, test and run dependency from Debian 12 packages.
# Safe to re-run; skips apt-get entirely when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  clang libclang-rt-14-dev          # libFuzzer targets and the fuzz preset
  libsdl2-dev libepoxy-dev libglm-dev
  libvorbis-dev                     # music: Ogg Vorbis tracks (vorbisfile)
  libasound2-dev                    # ALSA: its error printing kept quiet without a sound card
  libopenmesh-dev                   # half-edge meshes for adjacency recovery
  libgtest-dev
  fteqcc                            # compiles the QuakeC test programs (tests/qc)
  libpng-dev zlib1g-dev             # screenshots (PNG)
  libgl1-mesa-dri libegl-mesa0      # headless OpenGL (llvmpipe) for tests
  python3-matplotlib                # demos/bench_report.py: the benchmark report's charts
  libembree-dev                     # vo_reference: ray-traced obscurance reference (a tool)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" = 0 ] || SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
