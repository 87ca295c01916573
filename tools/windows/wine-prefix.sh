# Sourced by .ci/windows-check.sh and tools/online/wine-joiner.sh: wine_prefix DIR LOG finds wine
# ($wine) and its server ($wineserver) and makes a wine prefix in DIR once (kept between runs):
# no debug output, Windows 10 (the .NET runtime needs it), no Mono or Gecko offered, no audio
# driver (the game then falls silent with one line, as on a Linux machine without a sound card).
# W^X off: wine 8 crashes in the runtime's finalizer of dynamic methods with it on (real Windows
# does not need this).
wine_prefix() {
  wine=/usr/lib/wine/wine64
  [ -x "$wine" ] || wine="$(command -v wine64 || command -v wine)"
  wineserver=/usr/lib/wine/wineserver64
  [ -x "$wineserver" ] || wineserver="$(command -v wineserver)"
  export WINEPREFIX="$1" WINEDEBUG=-all DOTNET_EnableWriteXorExecute=0
  if [ ! -f "$WINEPREFIX/.billiards-ready" ]; then
    rm -rf "$WINEPREFIX"
    # mscoree and mshtml off while the prefix is made: no Mono or Gecko to offer. Not later: wine
    # needs its mscoree to load the .NET runtime's assemblies.
    WINEDLLOVERRIDES="mscoree,mshtml=" "$wine" wineboot --init >"$2" 2>&1
    "$wine" reg add 'HKCU\Software\Wine' /v Version /d win10 /f >/dev/null 2>&1
    "$wine" reg add 'HKCU\Software\Wine\Drivers' /v Audio /d '' /f >/dev/null 2>&1
    "$wineserver" -w
    touch "$WINEPREFIX/.billiards-ready"
  fi
}
