#!/bin/sh
# A whole networked 8-ball game between two processes on this machine: the host and the joiner,
# each in its own X display (Xvfb when none is running there) and driven by its own script
# (assets/scripts/online-eight-ball-host.json and -join.json), play on 127.0.0.1; then both
# records are compared byte for byte and each is checked by `replay --verify`.
# Usage: tools/online/two-processes.sh [BILLIARDS] [HOST_DISPLAY] [JOIN_DISPLAY] [OUT_DIR]
# Prints each step and exits 0 when the records are the same and both verify.
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/src/Billiards.App/bin/Release/net10.0/billiards}
hd=${2:-:14}
jd=${3:-:15}
out=${4:-$(mktemp -d)}
port=${PORT:-7538}
code=K7PQ2M
mkdir -p "$out"
. "$here/tools/online/displays.sh"
start_displays 1280x800x24 "$hd" "$jd"
trap 'for p in $started; do kill "$p" 2>/dev/null || true; done' EXIT
echo "host: DISPLAY=$hd billiards host --port $port --code $code --players Anna,Ben --script online-eight-ball-host.json --record $out/host.json"
DISPLAY=$hd "$bin" host --port "$port" --code "$code" --players Anna,Ben \
  --script "$here/assets/scripts/online-eight-ball-host.json" --record "$out/host.json" >"$out/host.out" 2>"$out/host.err" &
host=$!
sleep 2
echo "join: DISPLAY=$jd billiards join 127.0.0.1:$port --code $code --script online-eight-ball-join.json --record $out/join.json"
DISPLAY=$jd "$bin" join "127.0.0.1:$port" --code "$code" \
  --script "$here/assets/scripts/online-eight-ball-join.json" --record "$out/join.json" >"$out/join.out" 2>"$out/join.err" &
join=$!
jrc=0; wait "$join" || jrc=$?
hrc=0; wait "$host" || hrc=$?
echo "exit codes: host $hrc, join $jrc"
cat "$out/host.out"
cmp "$out/host.json" "$out/join.json"
echo "the two records are the same bytes ($(wc -c <"$out/host.json") bytes)"
"$bin" replay "$out/host.json" --verify
"$bin" replay "$out/join.json" --verify
# The latency: each stroke sent on one side and its cue starting to turn on the other (UTC stamps).
python3 - "$out/host.err" "$out/join.err" <<'PY' || true
import re, sys
def stamps(path, what):
    out = {}
    for line in open(path):
        m = re.search(r"shot (\d+): stroke " + what + r".* at (\d+):(\d+):([\d.]+)", line)
        if m:
            out[int(m.group(1))] = int(m.group(2)) * 3600 + int(m.group(3)) * 60 + float(m.group(4))
    return out
h, j = sys.argv[1], sys.argv[2]
gaps = []
for sent, seen in ((stamps(h, "sent"), stamps(j, "arrived")), (stamps(j, "sent"), stamps(h, "arrived"))):
    gaps += [(k, (seen[k] - sent[k]) * 1000) for k in sent if k in seen]
for k, ms in sorted(gaps):
    print(f"shot {k}: sent to the cue turning on the other side {ms:.1f} ms")
PY
