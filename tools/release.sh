#!/usr/bin/env bash
# The release artifacts, from this checkout, into artifacts/release/ (git-ignored):
#   billiards-VERSION-win-x64.zip       the self-contained win-x64 folder (billiards.exe, the .NET
#                                       runtime, GLFW, Assimp and OpenAL Soft DLLs, the assets)
#   billiards-VERSION-linux-x64.tar.gz  the self-contained linux-x64 folder (run ./billiards)
#   billiards_VERSION_amd64.deb         the same folder in /opt/billiards, `billiards` on the path,
#                                       the desktop entry and the icon; depends on the Debian
#                                       packages of the native libraries the App binds
#   SHA256SUMS                          their SHA-256 sums (sha256sum -c SHA256SUMS)
# VERSION is the one <Version> of Directory.Build.props. Usage: tools/release.sh [OUT]
# The archives are reproducible for a commit: file times are the commit's, owners root.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
out="${1:-$repo/artifacts/release}"
version="$(sed -n 's:.*<Version>\(.*\)</Version>.*:\1:p' Directory.Build.props)"
[ -n "$version" ] || { echo "release: no <Version> in Directory.Build.props"; exit 1; }
epoch="$(git log -1 --format=%ct 2>/dev/null || echo 0)"
export SOURCE_DATE_EPOCH="$epoch"

export DEBIAN_FRONTEND=noninteractive
missing=""
for p in dpkg-dev python3; do dpkg -s "$p" >/dev/null 2>&1 || missing="$missing $p"; done
if [ -n "$missing" ]; then
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends $missing >/dev/null
fi

work="$out/work"
rm -rf "$out"
mkdir -p "$work"
publish() { # rid folder
  dotnet publish src/Billiards.App -c Release -r "$1" -o "$2" -v quiet -nologo >"$work/publish-$1.log" 2>&1 \
    || { tail -n 30 "$work/publish-$1.log"; echo "release: $1 publish failed"; exit 1; }
  # Debug databases and XML docs are for developers, not players.
  find "$2" -maxdepth 1 \( -name '*.pdb' -o -name '*.xml' -o -name '*.dbg' \) -delete
}

linux_name="billiards-$version-linux-x64"
win_name="billiards-$version-win-x64"
publish linux-x64 "$work/$linux_name"
publish win-x64 "$work/$win_name"
cp CHANGELOG.md "$work/$linux_name/"
cp CHANGELOG.md "$work/$win_name/"

# The archives: sorted names, the commit's time, root's files, readable by all (executables
# executable by all; the packages' files come with their own modes).
chmod -R u=rwX,go=rX "$work/$linux_name" "$work/$win_name"
find "$work/$linux_name" "$work/$win_name" -exec touch -h -d "@$epoch" {} +
tar --sort=name --owner=0 --group=0 --numeric-owner --mtime="@$epoch" -C "$work" -cf - "$linux_name" \
  | gzip -n -9 > "$out/$linux_name.tar.gz"
python3 - "$work" "$win_name" "$out/$win_name.zip" "$epoch" <<'EOF'
import os, sys, time, zipfile
root, name, target, epoch = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
stamp = time.gmtime(max(epoch, 315532800))[:6]   # zip times start in 1980
with zipfile.ZipFile(target, 'w', zipfile.ZIP_DEFLATED, compresslevel=9) as z:
    for folder, dirs, files in os.walk(os.path.join(root, name)):
        dirs.sort()
        for f in sorted(files):
            path = os.path.join(folder, f)
            info = zipfile.ZipInfo(os.path.relpath(path, root).replace(os.sep, '/'), stamp)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (0o755 if os.access(path, os.X_OK) else 0o644) << 16
            with open(path, 'rb') as src:
                z.writestr(info, src.read())
EOF

# The .deb: /opt/billiards, /usr/bin/billiards, the desktop entry, the icon, the copyright file.
deb="$work/deb"
mkdir -p "$deb/DEBIAN" "$deb/opt" "$deb/usr/bin" "$deb/usr/share/applications" \
  "$deb/usr/share/icons/hicolor/256x256/apps" "$deb/usr/share/doc/billiards"
cp -a "$work/$linux_name" "$deb/opt/billiards"
cat > "$deb/usr/bin/billiards" <<'EOF'
#!/bin/sh
# The game and its command line, installed in /opt/billiards (its assets beside it).
exec /opt/billiards/billiards "$@"
EOF
chmod 755 "$deb/usr/bin/billiards"
cp assets/linux/billiards.desktop "$deb/usr/share/applications/billiards.desktop"
cp assets/icons/billiards.png "$deb/usr/share/icons/hicolor/256x256/apps/billiards.png"
{ cat LICENSE; echo; cat THIRD-PARTY-NOTICES; } > "$deb/usr/share/doc/billiards/copyright"
gzip -n -9 -c CHANGELOG.md > "$deb/usr/share/doc/billiards/changelog.gz"
size="$(du -sk --exclude=DEBIAN "$deb" | cut -f1)"
# The native libraries the App loads at run time (src/Billiards.App/Native): GLFW, Assimp, OpenAL
# Soft, EGL and Mesa's drivers for the headless renderer, libGL for GLFW's windows; and what the
# self-contained .NET runtime itself links.
depends="libc6, libgcc-s1, libstdc++6, libglfw3 | libglfw3-wayland, libassimp5, libopenal1, libegl1, libgl1, libegl-mesa0, libgl1-mesa-dri, libgbm1"
cat > "$deb/DEBIAN/control" <<EOF
Package: billiards
Version: $version
Architecture: amd64
Maintainer: The Billiards authors <billiards@localhost>
Installed-Size: $size
Depends: $depends
Section: games
Priority: optional
Description: 3D pool game and billiards physics engine
 8-ball, 9-ball, 10-ball, straight pool and snooker against a person or the
 computer, with practice drills and instant replay, on an event-based
 physics engine. Also a command line (billiards simulate, render, selfplay,
 replay) for headless simulation and rendering.
EOF
find "$deb" -exec touch -h -d "@$epoch" {} +
dpkg-deb --root-owner-group -Zxz --build "$deb" "$out/billiards_${version}_amd64.deb" >/dev/null

rm -rf "$work"
(cd "$out" && sha256sum "$win_name.zip" "$linux_name.tar.gz" "billiards_${version}_amd64.deb" > SHA256SUMS)
echo "release $version in $out:"
(cd "$out" && ls -l --time-style=+ "$win_name.zip" "$linux_name.tar.gz" "billiards_${version}_amd64.deb" SHA256SUMS | awk '{print "  " $NF " (" $5 " bytes)"}')
