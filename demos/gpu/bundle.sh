#!/usr/bin/env bash
# Bundles the release build, the shared libraries it needs beyond glibc and libstdc++, and the
# game data (without music and sounds) into .gpu/ (ignored by git: add /.gpu/ to
# .git/info/exclude), for a machine that has a GPU but none of our build dependencies; then
# run demos/gpu/run.sh there from a copy of the repository that holds .gpu/ (and .gl/, the
# libglvnd packages: apt-get download libegl1 libglvnd0 libopengl0 libgl1 libglx0 libgles2).
set -euo pipefail
source "$(dirname "$0")/../common.sh"
# Checked before the old bundle is removed, so a failed bundle leaves the last one whole.
require_build
require_data
cd "$root"
rm -rf .gpu/build .gpu/lib .gpu/data
mkdir -p .gpu/build .gpu/lib .gpu/data
cp -a "$build/bin" .gpu/build/
rm -f .gpu/build/bin/serverbench .gpu/build/bin/demotool .gpu/build/bin/pak .gpu/build/bin/mdltool
for f in .gpu/build/bin/nprquake .gpu/build/bin/plugins/*.so; do
    ldd "$f" | awk '/=> \// {print $3}'
done | sort -u | grep -v -E '/(libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s|ld-linux[^/]*)\.so' |
    while read -r lib; do cp -L "$lib" .gpu/lib/; done
cp -a "$data/lq1" .gpu/data/ && rm -rf .gpu/data/lq1/music .gpu/data/lq1/sound
mv .gpu/build/bin/nprquake .gpu/build/bin/nprquake.real
printf "%s\n" "#!/bin/sh" "here=\$(dirname \"\$0\")" "LD_LIBRARY_PATH=\$here/../../lib\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH} exec \"\$here/nprquake.real\" \"\$@\"" > .gpu/build/bin/nprquake
chmod +x .gpu/build/bin/nprquake
du -sh .gpu/* .gl
