#!/bin/sh
# "Play online" through the start menu, two processes on this machine, each in its own X display
# (Xvfb when none is running there), driven by xdotool with the keyboard: the host chooses
# Play online, Host a game, Host and shows its code; the joiner chooses Play online, Join a game
# and types 127.0.0.1 and that code; the host breaks. Takes the pictures of docs/network.md
# (tools/docs/figures.sh online runs it).
# Usage: tools/online/menu-screens.sh [BILLIARDS] [HOST_DISPLAY] [JOIN_DISPLAY] [OUT_DIR]
set -eu
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/src/Billiards.App/bin/Release/net10.0/billiards}
hd=${2:-:71}
jd=${3:-:72}
out=${4:-$here/docs}
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
out=$(mkdir -p "$out" && cd "$out" && pwd)
work=$(mktemp -d)
. "$here/tools/online/displays.sh"
start_displays 1280x720x24 "$hd" "$jd"
pids=""
trap 'for p in $pids $started; do kill "$p" 2>/dev/null || true; done' EXIT
# Each side its own settings and data folder: the user's are not touched.
for side in host join; do mkdir -p "$work/$side"; done
(cd "$work" && DISPLAY=$hd XDG_CONFIG_HOME=$work/host BILLIARDS_DATA_DIR=$work/host exec "$bin" 2>"$work/host.err") &
pids="$pids $!"
(cd "$work" && DISPLAY=$jd XDG_CONFIG_HOME=$work/join BILLIARDS_DATA_DIR=$work/join exec "$bin" 2>"$work/join.err") &
pids="$pids $!"
keys() { d=$1; shift; for k in "$@"; do DISPLAY=$d xdotool key "$k"; sleep 0.4; done; }
sleep 15
# The pointer out of the way (a button under it takes the focus), the focus on the first button
# (Play); Tab: the next, Play online; its first button hosts, its second joins; Host is focused on
# the game's page.
for d in "$hd" "$jd"; do DISPLAY=$d xdotool mousemove 1 1; keys "$d" Up Up Up Up Up Up Up; done
keys "$hd" Tab Return Return Return
sleep 3
code=$(sed -n 's/.*with the code \([A-Z0-9]*\).*/\1/p' "$work/host.err" | tail -n 1)
if [ -z "$code" ]; then echo "the host shows no code:"; cat "$work/host.err"; exit 1; fi
echo "host: code $code"
DISPLAY=$hd import -window root "$out/online-host-code.png"
keys "$jd" Tab Return Tab Return
DISPLAY=$jd xdotool type --delay 100 "127.0.0.1"
keys "$jd" Return
DISPLAY=$jd xdotool type --delay 100 "$code"
sleep 1
DISPLAY=$jd import -window root "$out/online-join-entry.png"
keys "$jd" Return
sleep 6
# The host breaks at a good pace; the joiner's window shows the host's cue turning and striking.
keys "$hd" w w w w w w w w space
# Both tables at rest after the break, the same balls where they lie.
sleep ${AFTER_BREAK:-15}
DISPLAY=$hd import -window root "$out/online-game-host.png"
DISPLAY=$jd import -window root "$out/online-game-join.png"
cat "$work/host.err" "$work/join.err"
echo "pictures in $out: online-host-code.png online-join-entry.png online-game-host.png online-game-join.png"
