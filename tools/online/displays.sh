# Sourced by the scripts of tools/online: start_displays SIZE DISPLAY... starts Xvfb (a screen of
# SIZE, e.g. 1280x720x24) on each display that has no X server yet; $started lists the Xvfb
# processes it started, for the script to kill when it ends.
started=""
start_displays() {
  size=$1
  shift
  for d in "$@"; do
    if ! DISPLAY=$d xdpyinfo >/dev/null 2>&1; then
      Xvfb "$d" -screen 0 "$size" >/dev/null 2>&1 &
      started="$started $!"
      sleep 1
    fi
  done
}
