#!/usr/bin/env bash
# The game's last frame as a picture: plays an input script in the window on $DISPLAY (an Xvfb
# screen of 1280x720, e.g. `Xvfb :99 -screen 0 1280x720x24 &`) and keeps the screen as it was
# when the script's duration ended and the game closed.
#   tools/docs/window-shot.sh OUT.png SCRIPT.json [play options...]
set -euo pipefail
out=$1 script=$2
shift 2
cd "$(dirname "$0")/../.."
app=src/Billiards.App/bin/Release/net10.0/billiards
[ -x "$app" ] || dotnet build src/Billiards.App -c Release -v quiet >/dev/null
: "${DISPLAY:?window-shot.sh needs a display (an Xvfb screen of 1280x720)}"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$app" play --script "$script" "$@" &
game=$!
n=0
# Screens taken one after the other while the game runs; the last whole one is its last frame.
while kill -0 "$game" 2>/dev/null; do
  if import -window root "$tmp/next.png" 2>/dev/null && kill -0 "$game" 2>/dev/null; then
    mv "$tmp/next.png" "$tmp/last.png"
    n=$((n + 1))
  fi
  sleep 0.2
done
wait "$game"
[ "$n" -gt 0 ] || { echo "window-shot.sh: no screen taken while the game ran" >&2; exit 1; }
cp "$tmp/last.png" "$out"
