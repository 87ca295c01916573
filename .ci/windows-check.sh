#!/usr/bin/env bash
# The Windows check (called by .ci/run): publish win-x64 from this checkout, with the native DLLs
# of tools/windows/build-natives.sh, and run billiards.exe under wine (Debian's wine64) with Xvfb:
#   --version prints the one version;
#   simulate gives the Linux build's results bit for bit (every shipped scene);
#   render writes a table PNG that is not blank;
#   play --script assets/scripts/eight-ball-game.json --record plays the whole game to its end,
#     the Linux build's replay --verify finds every shot the same, and the Linux build playing the
#     same script records the same game;
#   host on Linux and join under wine play a whole 8-ball game by their scripts, the two records
#     the same and each verifying (tools/online/wine-joiner.sh);
#   selfplay records the Linux build's games byte for byte, and they verify on Linux;
#   render-audio writes the Linux build's WAV byte for byte.
# Installs what it needs with apt-get when missing. Everything it makes stays in build/ (git-ignored):
# the native DLLs (cached between local runs), the wine prefix, the published folder and the outputs.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
start=$(date +%s)
step_start=$start
step() { local now; now=$(date +%s); echo "windows check: $1 ($((now - step_start)) s)"; step_start=$now; }

export DEBIAN_FRONTEND=noninteractive
need="wine64 xvfb xauth python3 libgl1-mesa-dri libegl-mesa0"
missing=""
for p in $need; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi
step "packages"

bash tools/windows/build-natives.sh
step "native DLLs"

out="$repo/build/windows-check"
rm -rf "$out/publish" "$out/run"
mkdir -p "$out/run"
dotnet publish src/Billiards.App -c Release -r win-x64 -o "$out/publish" -v quiet -nologo >"$out/publish.log" 2>&1 \
  || { tail -n 30 "$out/publish.log"; echo "windows check: win-x64 publish failed"; exit 1; }
for f in billiards.exe glfw3.dll assimp.dll OpenAL32.dll libSkiaSharp.dll THIRD-PARTY-NOTICES assets/models/pool-9ft.obj; do
  [ -f "$out/publish/$f" ] || { echo "windows check: the published folder lacks $f"; exit 1; }
done
dotnet build src/Billiards.App -c Release -v quiet -nologo >"$out/build.log" 2>&1 \
  || { tail -n 30 "$out/build.log"; echo "windows check: Linux build failed"; exit 1; }
linux="$repo/src/Billiards.App/bin/Release/net10.0/billiards"
step "publish"

# --- wine: its own prefix in build/ (tools/windows/wine-prefix.sh says how it is made).
. tools/windows/wine-prefix.sh
wine_prefix "$out/wineprefix" "$out/wineboot.log"
step "wine prefix"

# A free display number (WINDOWS_CHECK_DISPLAY=:N chooses one).
display="${WINDOWS_CHECK_DISPLAY:-}"
for n in $( [ -z "$display" ] && seq 90 130); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=":$n"; break; fi
done
[ -n "$display" ] || { echo "windows check: no free X display"; exit 1; }
Xvfb "$display" -screen 0 1280x800x24 -nolisten tcp >"$out/xvfb.log" 2>&1 &
xvfb=$!
cleanup() { "$wineserver" -k >/dev/null 2>&1 || true; kill "$xvfb" >/dev/null 2>&1 || true; }
trap cleanup EXIT
export DISPLAY="$display"
for _ in $(seq 50); do [ -e "/tmp/.X11-unix/X${display#:}" ] && break; sleep 0.1; done

exe="$out/publish/billiards.exe"
run="$out/run"
win() { "$wine" "$exe" "$@"; }
fail() { echo "windows check: $1"; exit 1; }

version="$(sed -n 's:.*<Version>\(.*\)</Version>.*:\1:p' Directory.Build.props)"
got="$(win --version | tr -d '\r')"
[ "$got" = "billiards $version" ] || fail "--version printed '$got', not 'billiards $version'"

# simulate: every shipped scene, under wine and on Linux, the same results bit for bit (the
# wall-clock time aside).
find assets/scenes -name '*.json' | sort | python3 -c '
import json, sys
for path in sys.stdin.read().split():
    print(json.dumps(json.load(open(path))))' > "$run/scenes.jsonl"
win simulate --batch "$(realpath --relative-to=. "$run/scenes.jsonl")" --out "$(realpath --relative-to=. "$run/scenes.windows.jsonl")" --threads 1 >/dev/null 2>&1 || [ $? = 3 ]
"$linux" simulate --batch "$(realpath --relative-to=. "$run/scenes.jsonl")" --out "$run/scenes.linux.jsonl" --threads 1 >/dev/null 2>&1 || [ $? = 3 ]
python3 - "$run/scenes.windows.jsonl" "$run/scenes.linux.jsonl" <<'EOF' || fail "simulate differs between Windows and Linux"
import json, sys
def lines(path):
    out = []
    for line in open(path, newline=''):
        d = json.loads(line)
        d.get('stats', {}).pop('wall_ms', None)
        out.append(json.dumps(d, sort_keys=True))
    return out
w, l = lines(sys.argv[1]), lines(sys.argv[2])
bad = [i for i, (a, b) in enumerate(zip(w, l)) if a != b]
if len(w) != len(l) or bad or not w:
    print(f"{len(w)} and {len(l)} results; scenes that differ: {bad[:10]}")
    sys.exit(1)
print(f"windows check: simulate, {len(w)} shipped scenes, the same results bit for bit")
EOF
step "simulate"

win render assets/scenes/eight-ball-break.json --out "$(realpath --relative-to=. "$run/table.png")" >/dev/null
python3 - "$run/table.png" <<'EOF' || fail "render wrote a blank or unreadable PNG"
import struct, sys, zlib
data = open(sys.argv[1], 'rb').read()
assert data[:8] == b'\x89PNG\r\n\x1a\n'
pos, idat, width, height, colour = 8, b'', 0, 0, 0
while pos < len(data):
    n, kind = struct.unpack('>I4s', data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b'IHDR':
        width, height, depth, colour = struct.unpack('>IIBB', body[:10])
    elif kind == b'IDAT':
        idat += body
    pos += 12 + n
raw = zlib.decompress(idat)
channels = {2: 3, 6: 4}[colour]
stride = width * channels + 1
# The distinct colours of a sample of pixels (filter bytes aside, the raw bytes still tell apart
# a uniform image from a table): a blank frame has one or two.
sample = {raw[r * stride + 1 + c * channels: r * stride + 1 + (c + 1) * channels] for r in range(0, height, 8) for c in range(0, width, 8)}
assert width >= 640 and height >= 360 and len(sample) > 200, (width, height, len(sample))
print(f"windows check: render, a {width}x{height} table PNG ({len(sample)} distinct sampled values)")
EOF
step "render"

win play --script assets/scripts/eight-ball-game.json --record "$(realpath --relative-to=. "$run/W.json")" >"$run/play.log" 2>&1 \
  || { cat "$run/play.log"; fail "play --script failed under wine"; }
python3 - "$run/W.json" <<'EOF' || fail "the scripted game did not reach its end"
import json, sys
shots = json.load(open(sys.argv[1]))['shots']
last = shots[-1]['ruling']
assert last['game_over'], last
print(f"windows check: play, the scripted 8-ball game to its end in {len(shots)} shots: {last['message']}")
EOF
"$linux" replay "$run/W.json" --verify > "$run/verify.json"
python3 - "$run/verify.json" <<'EOF' || fail "the game played under wine does not replay on Linux"
import json, sys
v = json.load(open(sys.argv[1]))
assert v['shots'] > 0 and v['same'] == v['shots'] and v['first_difference'] is None, v
print(f"windows check: replay --verify on Linux, {v['same']} of {v['shots']} shots the same")
EOF
# The Linux build playing the same script makes the same game, byte for byte (Windows writes its
# JSON with CRLF line ends, nothing else differs).
"$linux" play --script assets/scripts/eight-ball-game.json --record "$run/L.json" >"$run/play.linux.log" 2>&1 \
  || { cat "$run/play.linux.log"; fail "play --script failed on Linux"; }
cmp <(tr -d '\r' < "$run/W.json") "$run/L.json" >/dev/null || fail "the scripted game differs between Windows and Linux"
echo "windows check: play, the Linux build's game byte for byte"
step "play and replay"

# Over the network: the Linux build hosts, this Windows build joins under wine, each playing its
# script of a whole 8-ball game; the two records the same and each verifies (about a minute).
WINE_EXE="$exe" HOST_DISPLAY="$display" JOIN_DISPLAY="$display" PORT="${WINDOWS_CHECK_PORT:-7591}" \
  tools/online/wine-joiner.sh "$out/wine-joiner" >"$run/wine-joiner.log" 2>&1 \
  || { cat "$run/wine-joiner.log"; fail "the networked game with a wine joiner failed"; }
grep "records are\|passed in" "$run/wine-joiner.log"
step "online: a wine joiner"

win selfplay --rules eight-ball --games 2 --levels 2,3 --seed 5 --threads 1 --out "$(realpath --relative-to=. "$run/selfplay.windows.jsonl")" --summary "$(realpath --relative-to=. "$run/selfplay.windows.json")" >/dev/null 2>&1
"$linux" selfplay --rules eight-ball --games 2 --levels 2,3 --seed 5 --threads 1 --out "$run/selfplay.linux.jsonl" --summary "$run/selfplay.linux.json" >/dev/null 2>&1
cmp <(tr -d '\r' < "$run/selfplay.windows.jsonl") "$run/selfplay.linux.jsonl" >/dev/null || fail "selfplay's games differ between Windows and Linux"
"$linux" replay "$run/selfplay.windows.jsonl" --verify > "$run/selfplay.verify.json"
python3 - "$run/selfplay.verify.json" <<'EOF' || fail "the self-play games played under wine do not replay on Linux"
import json, sys
for line in open(sys.argv[1]):
    v = json.loads(line)
    assert v['shots'] > 0 and v['same'] == v['shots'] and v['first_difference'] is None, v
print("windows check: selfplay, the Linux build's games byte for byte, and they verify on Linux")
EOF
step "selfplay"

win render-audio assets/scenes/eight-ball-break.json --out "$(realpath --relative-to=. "$run/break.windows.wav")" >/dev/null
"$linux" render-audio assets/scenes/eight-ball-break.json --out "$run/break.linux.wav" >/dev/null
cmp "$run/break.windows.wav" "$run/break.linux.wav" || fail "render-audio's WAV differs between Windows and Linux"
echo "windows check: render-audio, the same WAV byte for byte ($(stat -c %s "$run/break.linux.wav") bytes)"
step "render-audio"

echo "windows check: passed in $(( $(date +%s) - start )) s"
