#!/usr/bin/env bash
# A whole networked 8-ball game between the Linux build as the host and the Windows build
# (win-x64, under wine) as the joiner, each under Xvfb and driven by its own script
# (assets/scripts/online-eight-ball-host.json and -join.json), both with --record; then the two
# records are compared byte for byte (CRLF line ends would be the only difference allowed) and `replay --verify` checks each (the host's with the Linux build, the
# joiner's with both builds). Prints the time of each step.
# Usage: tools/online/wine-joiner.sh [OUT_DIR]   (default build/wine-joiner, git-ignored)
#   WINE_EXE=path/billiards.exe   a published win-x64 build (default: published into OUT_DIR)
#   WINEPREFIX=dir                the wine prefix (default: OUT_DIR/wineprefix, made once)
#   HOST_DISPLAY, JOIN_DISPLAY    the X displays (default :74 and :75; Xvfb started when none runs)
#   PORT                          the host's port (default 7539)
#   SHOTS=dir                     also a picture of each window 30 s into the game (host.png, join.png)
# Needs the native DLLs in build/windows-natives/win-x64 (tools/windows/build-natives.sh) to publish.
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$here/build/wine-joiner}
mkdir -p "$out"
out=$(cd "$out" && pwd)
hd=${HOST_DISPLAY:-:74}
jd=${JOIN_DISPLAY:-:75}
port=${PORT:-7539}
code=K7PQ2M
start=$(date +%s)
step_start=$start
step() { local now; now=$(date +%s); echo "wine joiner: $1 ($((now - step_start)) s)"; step_start=$now; }
fail() { echo "wine joiner: $1"; exit 1; }

linux="$here/src/Billiards.App/bin/Release/net10.0/billiards"
[ -x "$linux" ] || dotnet build "$here/src/Billiards.App" -c Release -v quiet -nologo >"$out/build.log" 2>&1 \
  || { tail -n 30 "$out/build.log"; fail "Linux build failed"; }
exe=${WINE_EXE:-}
if [ -z "$exe" ]; then
  rm -rf "$out/publish"
  dotnet publish "$here/src/Billiards.App" -c Release -r win-x64 -o "$out/publish" -v quiet -nologo >"$out/publish.log" 2>&1 \
    || { tail -n 30 "$out/publish.log"; fail "win-x64 publish failed"; }
  exe="$out/publish/billiards.exe"
  step "publish win-x64"
fi
. "$here/tools/windows/wine-prefix.sh"
wine_prefix "${WINEPREFIX:-$out/wineprefix}" "$out/wineboot.log"
step "wine prefix"

. "$here/tools/online/displays.sh"
start_displays 1280x800x24 "$hd" "$jd"
run="$out/run"
rm -rf "$run"
mkdir -p "$run"
cd "$run"
pids=""
trap 'for p in $pids; do kill "$p" 2>/dev/null || true; done; "$wineserver" -k >/dev/null 2>&1 || true; for p in $started; do kill "$p" 2>/dev/null || true; done' EXIT
echo "host (Linux): DISPLAY=$hd billiards host --port $port --code $code --players Anna,Ben --script online-eight-ball-host.json --record host.json"
DISPLAY=$hd "$linux" host --port "$port" --code "$code" --players Anna,Ben \
  --script "$here/assets/scripts/online-eight-ball-host.json" --record host.json >host.out 2>host.err &
host=$!
pids="$host"
cp "$here/assets/scripts/online-eight-ball-join.json" join-script.json
sleep 2
echo "join (Windows, wine): DISPLAY=$jd wine billiards.exe join 127.0.0.1:$port --code $code --script join-script.json --record join.json"
game_start=$(date +%s)
if [ -n "${SHOTS:-}" ]; then
  mkdir -p "$SHOTS"
  (sleep 30; DISPLAY=$hd import -window root "$SHOTS/host.png"; DISPLAY=$jd import -window root "$SHOTS/join.png") &
fi
jrc=0
DISPLAY=$jd "$wine" "$exe" join "127.0.0.1:$port" --code "$code" --script join-script.json --record join.json >join.out 2>join.err || jrc=$?
hrc=0
wait "$host" || hrc=$?
pids=""
echo "exit codes: host $hrc, join $jrc; the game took $(( $(date +%s) - game_start )) s from the joiner's start"
[ "$hrc" = 0 ] && [ "$jrc" = 0 ] || { tail -n 20 host.err join.err; fail "a side failed"; }
step "the game"
grep -c "stroke sent" host.err join.err || true
if cmp -s join.json host.json; then
  echo "wine joiner: the two records are byte for byte the same ($(stat -c %s host.json) bytes)"
else
  # Windows may write CRLF line ends; nothing else may differ.
  cmp <(tr -d '\r' < join.json) host.json || fail "the two records differ"
  echo "wine joiner: the two records are the same but for CRLF line ends ($(stat -c %s host.json) and $(stat -c %s join.json) bytes)"
fi
"$linux" replay host.json --verify | tee host.verify.json
"$linux" replay join.json --verify | tee join.verify.json
"$wine" "$exe" replay join.json --verify | tr -d '\r' | tee join.wine.verify.json
python3 - host.verify.json join.verify.json join.wine.verify.json <<'PY' || fail "replay --verify found a difference"
import json, sys
for path in sys.argv[1:]:
    v = json.load(open(path))
    assert v['shots'] > 0 and v['same'] == v['shots'] and v['first_difference'] is None, (path, v)
PY
step "compare and verify"
echo "wine joiner: passed in $(( $(date +%s) - start )) s"
