#!/usr/bin/env bash
# Makes the pictures of README.md and docs/ again from the code as it is; each picture's caption
# names its line here. Run from anywhere; needs a Release build of the App (built if missing).
#   tools/docs/figures.sh            the renders and the sound's waveform (offscreen, no display)
#   tools/docs/figures.sh window     also the window shots of hud-aiming, result-panel and instant-replay
#   tools/docs/figures.sh reports    also the accuracy report and its cushion page (about a minute)
#   tools/docs/figures.sh online     also the online pictures: the host's code, the joiner's entry, both tables
# The other window shots (computer-turn, practice-*, flight/jump-in-window, flight/elevation-gauge)
# are taken by hand under Xvfb (import -window root) in the game their caption names.
set -euo pipefail
cd "$(dirname "$0")/../.."
app=src/Billiards.App/bin/Release/net10.0/billiards
[ -x "$app" ] || dotnet build src/Billiards.App -c Release -v quiet >/dev/null
billiards() { "$app" "$@"; }

# The front page's table, the rack up close, the room (rendering-and-sound.md).
billiards render assets/scenes/eight-ball.json --out docs/screenshot.png
billiards render assets/scenes/eight-ball.json --out docs/rack-close-up.png --camera=0.25,0,0.35,0.64,0,0,35 --width 800 --height 500
billiards render assets/scenes/eight-ball.json --out docs/room.png --camera=-2.6,-1.2,0.7,0,0,0.3,60 --width 800 --height 450
# The jump shot at the top of its hop (physics.md).
billiards render assets/scenes/flight/jump.json --out docs/flight/jump-mid-flight.png --at 0.19 --camera=-0.3,-1.1,0.25,-0.44,0,0.08,40 --width 960 --height 540
# The break's waveform with its events (rendering-and-sound.md).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
billiards render-audio assets/scenes/eight-ball-break.json --out "$tmp/break.wav"
billiards simulate assets/scenes/eight-ball-break.json --out "$tmp/break.json"
python3 docs/sound/waveform.py "$tmp/break.wav" "$tmp/break.json" docs/sound/break-waveform.svg

if [ "${1:-}" = online ]; then
  # "Play online" through the start menu (network.md): two processes, each under its own Xvfb
  # display (:71 and :72 unless HOST_DISPLAY, JOIN_DISPLAY say otherwise), driven by xdotool.
  tools/online/menu-screens.sh "$app" "${HOST_DISPLAY:-:71}" "${JOIN_DISPLAY:-:72}" docs
fi

if [ "${1:-}" = window ]; then
  # Window shots, each the last frame of an input script played under $DISPLAY (an Xvfb screen of
  # 1280x720: `Xvfb :99 -screen 0 1280x720x24 &`, then DISPLAY=:99); tools/docs/cut-script.py
  # stops a shipped script at the moment to show. The FPS numbers of the HUD vary from run to run.
  : "${DISPLAY:?figures.sh window needs a display (an Xvfb screen of 1280x720)}"
  shot() { tools/docs/window-shot.sh "$@" 2>/dev/null; }
  game=assets/scripts/game-against-the-computer.json
  python3 tools/docs/cut-script.py $game G 5 10 "$tmp/aim.json"
  shot docs/hud-aiming.png "$tmp/aim.json" --rules eight-ball --players Anna,cpu:3
  shot docs/result-panel.png $game --rules eight-ball --players Anna,cpu:3
  shot docs/three-cushion-aid.png assets/scripts/diamond-aid.json --drill corner-five
  shot docs/three-cushion-result.png assets/scripts/three-cushion-game.json assets/scenes/three-cushion-race.json --rules three-cushion --players Anna,computer:4
  python3 tools/docs/cut-script.py assets/scripts/instant-replay.json Space 2 6 "$tmp/replay.json" before
  shot docs/instant-replay.png "$tmp/replay.json" --players Anna,Ben
fi

if [ "${1:-}" = reports ]; then
  # The work-precision diagram and the cushion page (physics.md, accuracy/).
  billiards report accuracy --out docs/accuracy
fi
