#!/usr/bin/env bash
# Builds the native libraries the App binds, for Windows x64, from Debian's source packages with
# Debian's mingw-w64 cross compilers: glfw3.dll (GLFW), assimp.dll (Assimp, the OBJ importer only)
# and OpenAL32.dll (OpenAL Soft). libgcc, libstdc++, winpthread and zlib are linked in statically,
# so the three DLLs need nothing but Windows's own system DLLs (the script checks their imports).
#
# Usage: tools/windows/build-natives.sh [OUT]
#   OUT defaults to build/windows-natives/win-x64 (git-ignored). A second run with the same script,
#   toolchain file and source versions is a no-op (the stamp file in OUT says what was built).
#   The App's win-x64 publish copies OUT's DLLs next to billiards.exe (src/Billiards.App's
#   CopyWindowsNatives target) and runs this script when they are missing.
#
# Installs what it needs with apt-get (root) when missing. Nothing it builds is committed.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
out="${1:-$repo/build/windows-natives/win-x64}"
work="$(dirname "$out")/work"
toolchain="$here/mingw-w64-x86_64.cmake"

# The source packages, pinned: bookworm's (the suite this machine and CI run), except OpenAL Soft,
# whose bookworm source (1:1.19.1-2) the package mirror does not serve; trixie's 1.24.2 builds
# with bookworm's GCC 12.
glfw_version="3.3.8-1";         glfw_suite=bookworm
assimp_version="5.2.5~ds0-1";   assimp_suite=bookworm
zlib_version="1:1.2.13.dfsg-1"; zlib_suite=bookworm
openal_version="1:1.24.2-1";    openal_suite=trixie

stamp_text="$(cat "$0" "$toolchain" | sha256sum | cut -c1-16) glfw3=$glfw_version assimp=$assimp_version zlib=$zlib_version openal-soft=$openal_version"
dlls="glfw3.dll assimp.dll OpenAL32.dll"
if [ -f "$out/.stamp" ] && [ "$(cat "$out/.stamp")" = "$stamp_text" ]; then
  all=1; for d in $dlls; do [ -f "$out/$d" ] || all=0; done
  if [ "$all" = 1 ]; then echo "windows natives: cached in $out"; exit 0; fi
fi

# --- tools -----------------------------------------------------------------------------------
need="gcc-mingw-w64-x86-64-posix g++-mingw-w64-x86-64-posix binutils-mingw-w64-x86-64 libz-mingw-w64-dev cmake make libutfcpp-dev libstb-dev dpkg-dev xz-utils bzip2"
missing=""
for p in $need; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  echo "windows natives: installing$missing"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

# --- sources: apt-get source with a private list of deb-src lines (the system's lists untouched)
mkdir -p "$work/apt/lists/partial" "$work/src"
mirror="$(sed -n 's/^URIs: *\(http[^ ]*debian\)\/*$/\1/p' /etc/apt/sources.list.d/debian.sources 2>/dev/null | head -n 1)"
[ -n "$mirror" ] || mirror="$(sed -n 's/^deb \(\[[^]]*\] \)\{0,1\}\(http[^ ]*debian\)\/* .*/\2/p' /etc/apt/sources.list 2>/dev/null | head -n 1)"
[ -n "$mirror" ] || mirror="http://deb.debian.org/debian"
keyring=/usr/share/keyrings/debian-archive-keyring.gpg
{
  echo "deb-src [signed-by=$keyring] $mirror bookworm main"
  echo "deb-src [signed-by=$keyring] $mirror trixie main"
} > "$work/apt/sources.list"
apt_opts=(-o "Dir::Etc::sourcelist=$work/apt/sources.list" -o "Dir::Etc::sourceparts=-"
          -o "Dir::State::Lists=$work/apt/lists" -o "APT::Sandbox::User=root")
fetched() { ls "$work/src/$1"_*.orig.tar.* >/dev/null 2>&1; }
if ! fetched glfw3 || ! fetched assimp || ! fetched zlib || ! fetched openal-soft; then
  apt-get "${apt_opts[@]}" update -qq
  (cd "$work/src" && apt-get "${apt_opts[@]}" source -qq --download-only --tar-only \
      "glfw3=$glfw_version" "assimp=$assimp_version" "zlib=$zlib_version" "openal-soft=$openal_version")
fi
# One clean tree per library, from its upstream tarball (apt checked its hash against the
# signed Sources index).
unpack() { # package folder
  rm -rf "$work/$2" && mkdir -p "$work/$2"
  tar -xf "$(ls "$work/src/$1"_*.orig.tar.*)" -C "$work/$2" --strip-components=1
}
unpack glfw3 glfw
unpack assimp assimp
unpack zlib zlib
unpack openal-soft openal

jobs="$(nproc)"
configure() { # source build [cmake options...]
  local src="$1" build="$2"; shift 2
  cmake -S "$src" -B "$build" -DCMAKE_TOOLCHAIN_FILE="$toolchain" -DCMAKE_BUILD_TYPE=Release \
    -DBUILD_SHARED_LIBS=ON "$@" > "$build.configure.log" 2>&1 || { tail -n 30 "$build.configure.log"; exit 1; }
}
compile() { # build target
  cmake --build "$1" --target "$2" -j "$jobs" > "$1.build.log" 2>&1 || { tail -n 40 "$1.build.log"; exit 1; }
}

# --- GLFW ------------------------------------------------------------------------------------
configure "$work/glfw" "$work/glfw-build" -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF -DGLFW_BUILD_DOCS=OFF
compile "$work/glfw-build" glfw

# --- Assimp: Debian's source lacks its bundled zlib, unzip, utf8cpp and stb; zlib comes from
# libz-mingw-w64-dev, unzip from zlib's own contrib/minizip, utf8cpp and stb from their
# (header-only) Debian packages.
mkdir -p "$work/assimp/contrib/unzip" "$work/assimp/contrib/utf8cpp"
cp "$work/zlib/contrib/minizip/"{unzip.c,unzip.h,ioapi.c,ioapi.h,crypt.h} "$work/assimp/contrib/unzip/"
: > "$work/assimp/contrib/unzip/crypt.c"   # Assimp's list names a crypt.c; minizip keeps it all in crypt.h
ln -sfn /usr/include/utf8cpp "$work/assimp/contrib/utf8cpp/source"
ln -sfn /usr/include/stb "$work/assimp/contrib/stb"
mkdir -p "$work/assimp/code/res"   # and its version resource (*.rc is stripped too): a minimal one
cat > "$work/assimp/code/res/assimp.rc" <<'RC'
1 VERSIONINFO
FILEVERSION 5,2,5,0
PRODUCTVERSION 5,2,5,0
BEGIN
  BLOCK "StringFileInfo"
  BEGIN
    BLOCK "040904b0"
    BEGIN
      VALUE "FileDescription", "Open Asset Import Library (OBJ importer only)"
      VALUE "FileVersion", "5.2.5"
      VALUE "ProductName", "Assimp"
    END
  END
END
RC
configure "$work/assimp" "$work/assimp-build" \
  -DASSIMP_BUILD_ALL_IMPORTERS_BY_DEFAULT=OFF -DASSIMP_BUILD_OBJ_IMPORTER=ON \
  -DASSIMP_BUILD_ALL_EXPORTERS_BY_DEFAULT=OFF -DASSIMP_NO_EXPORT=ON \
  -DASSIMP_BUILD_ASSIMP_TOOLS=OFF -DASSIMP_BUILD_TESTS=OFF -DASSIMP_BUILD_SAMPLES=OFF \
  -DASSIMP_BUILD_ZLIB=OFF -DZLIB_LIBRARY_REL=/usr/x86_64-w64-mingw32/lib/libz.a -DZLIB_LIBRARY_DBG=/usr/x86_64-w64-mingw32/lib/libz.a -DASSIMP_BUILD_MINIZIP=ON -DASSIMP_WARNINGS_AS_ERRORS=OFF \
  -DASSIMP_INSTALL=OFF -DASSIMP_INJECT_DEBUG_POSTFIX=OFF -DLIBRARY_SUFFIX=
compile "$work/assimp-build" assimp

# --- OpenAL Soft: the Windows backends only (WASAPI, DirectSound, WinMM), no examples or utilities.
configure "$work/openal" "$work/openal-build" \
  -DALSOFT_UTILS=OFF -DALSOFT_EXAMPLES=OFF -DALSOFT_TESTS=OFF -DALSOFT_INSTALL=OFF \
  -DALSOFT_NO_CONFIG_UTIL=ON -DALSOFT_BACKEND_PIPEWIRE=OFF -DALSOFT_BACKEND_PULSEAUDIO=OFF \
  -DALSOFT_BACKEND_JACK=OFF -DALSOFT_BACKEND_PORTAUDIO=OFF -DALSOFT_BACKEND_SDL2=OFF
compile "$work/openal-build" OpenAL

# --- collect and check -------------------------------------------------------------------------
rm -rf "$out" && mkdir -p "$out"
find_one() { find "$1" -name "$2" -type f | head -n 1; }
cp "$(find_one "$work/glfw-build" glfw3.dll)" "$out/glfw3.dll"
cp "$(find_one "$work/assimp-build" 'libassimp*.dll')" "$out/assimp.dll"
cp "$(find_one "$work/openal-build" OpenAL32.dll)" "$out/OpenAL32.dll"
# Windows's own DLLs only: a mingw runtime DLL (libstdc++-6, libgcc_s_seh-1, libwinpthread-1) or
# zlib1.dll here would be missing on a clean Windows.
for d in $dlls; do
  for import in $(x86_64-w64-mingw32-objdump -p "$out/$d" | sed -n 's/^\s*DLL Name: //p'); do
    case "$(echo "$import" | tr 'A-Z' 'a-z')" in
      kernel32.dll|user32.dll|gdi32.dll|shell32.dll|advapi32.dll|ole32.dll|oleaut32.dll|winmm.dll|msvcrt.dll|api-ms-win-*|shlwapi.dll|imm32.dll|version.dll|setupapi.dll|uuid.dll|avrt.dll) ;;
      *) echo "windows natives: $d imports $import, which a clean Windows does not have" >&2; exit 1 ;;
    esac
  done
done
echo "$stamp_text" > "$out/.stamp"
ls -l "$out"
