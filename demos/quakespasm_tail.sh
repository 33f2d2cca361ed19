#!/usr/bin/env bash
# QuakeSpasm's own frame-time tail on a demo, to put beside ours (-benchmark prints the same
# figures). QuakeSpasm's timedemo reports only an average, so this runs it with `host_speeds 1`,
# which logs every frame's milliseconds (whole numbers: server + drawing + sound) to its
# -condebug log, and reads the median, 95th and 99th percentile and the 1% low from there.
#
# usage: demos/quakespasm_tail.sh DEMO [WxH]
#   DEMO  a demo name in the data (demo, demo2) or the path of a .dem file
# env:   QUAKESPASM_TIMEDEMO (default ../shared/tools/quakespasm_timedemo.sh), which sets up
#        QuakeSpasm's game dir in $PEER (default /tmp/peer) and gives its timedemo fps first
# Prints: quakespasm-tail DEMO WxH frames N median M 95th A 99th B 99th/median R 1%-low L fps
#         (avg F fps, low/avg Q)
set -euo pipefail
source "$(dirname "$0")/common.sh"
usage_lines=2,12
tool=${QUAKESPASM_TIMEDEMO:-$quakespasm_tool}
peer=${PEER:-/tmp/peer}
case ${1:-} in -h|--help|"") usage; exit 0 ;; esac
demo=$1
res=${2:-640x480}
[ -x "$quakespasm_bin" ] || die "quakespasm is not installed"
[ -f "$tool" ] || die "no $tool"
require_command xvfb-run "xvfb-run missing"

# The reference tool builds the game dir, copies a .dem file into it and times one run.
PEER=$peer bash "$tool" "$demo" "$res" 1 >&2
name=$(basename "$demo" .dem)
base=$peer/base
[ -f "$base/id1/$name.dem" ] || die "no $base/id1/$name.dem"

run=$(mktemp -d)
trap 'rm -rf "$run"' EXIT
cat > "$run/inner.sh" <<EOF
cd "$run"
"$quakespasm_bin" -basedir "$base" -nosound -width ${res%x*} -height ${res#*x} -window \
    -condebug +host_speeds 1 +timedemo "$name" > stdout.txt 2>&1 &
pid=\$!
for _ in \$(seq 2400); do
    grep -qE '^-?[0-9]+ frames +[0-9.]+ seconds' qconsole.log 2>/dev/null && break
    kill -0 \$pid 2>/dev/null || break
    sleep 0.5
done
kill -TERM \$pid 2>/dev/null; wait \$pid 2>/dev/null || true
EOF
xvfb-run -a -s "-screen 0 1280x1024x24" bash "$run/inner.sh"
log=$run/qconsole.log
[ -f "$log" ] || log=$base/id1/qconsole.log
/usr/bin/env python3 - "$log" "$name" "$res" <<'EOF'
import re, statistics, sys
path, name, res = sys.argv[1:4]
lines = open(path, errors="replace").read().splitlines()
done = [l for l in lines if re.match(r"^-?\d+ frames +[\d.]+ seconds", l)]
if not done:
    sys.exit("quakespasm_tail.sh: no timedemo line in " + path)
frames = int(done[-1].split()[0])
times = [int(m.group(1)) for l in lines for m in [re.match(r"^\s*(\d+) tot ", l)] if m]
times = times[-frames:]  # the counted frames are the last ones before the result
if len(times) < frames or not times:
    sys.exit("quakespasm_tail.sh: %d frame times for %d frames" % (len(times), frames))
s = sorted(times)
n = len(s)
median = statistics.median(s)
slowest = s[-max(1, n // 100):]
low = 1000.0 / (sum(slowest) / len(slowest))
avg = 1000.0 * n / max(sum(s), 1)
print("quakespasm-tail %s %s frames %d median %g 95th %d 99th %d 99th/median %.2f "
      "1%%-low %.1f fps (avg %.1f fps, low/avg %.2f)"
      % (name, res, n, median, s[int(n * 0.95)], s[int(n * 0.99)], s[int(n * 0.99)] / median,
         low, avg, low / avg))
EOF
