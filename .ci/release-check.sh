#!/usr/bin/env bash
# The release check (called by .ci/run): tools/release.sh makes the zip, the tarball and the .deb
# with their sums, and this looks into each without installing anything: the sums hold; the .deb's
# name, version, dependencies and files (/opt/billiards, /usr/bin/billiards, the desktop entry, the
# icon) are the ones docs/install.md promises, and its billiards and the tarball's run
# `--version` and `simulate` from another folder; the zip has billiards.exe with its DLLs.
set -euo pipefail
cd "$(dirname "$0")/.."
repo="$(pwd)"
start=$(date +%s)
version="$(sed -n 's:.*<Version>\(.*\)</Version>.*:\1:p' Directory.Build.props)"
out="$repo/artifacts/release"
fail() { echo "release check: $1"; exit 1; }

bash tools/release.sh "$out"
(cd "$out" && sha256sum --quiet -c SHA256SUMS) || fail "SHA256SUMS does not hold"
[ "$(wc -l < "$out/SHA256SUMS")" = 3 ] || fail "SHA256SUMS does not list the three artifacts"

deb="$out/billiards_${version}_amd64.deb"
[ "$(dpkg-deb -f "$deb" Package)" = billiards ] || fail "the .deb is not package billiards"
[ "$(dpkg-deb -f "$deb" Version)" = "$version" ] || fail "the .deb's version is not $version"
[ "$(dpkg-deb -f "$deb" Architecture)" = amd64 ] || fail "the .deb is not amd64"
depends="$(dpkg-deb -f "$deb" Depends)"
for p in libglfw3 libassimp5 libopenal1 libegl1 libgl1 libegl-mesa0 libgl1-mesa-dri libgbm1; do
  grep -qx "$p" <<< "$(tr ',|' '\n\n' <<< "$depends" | sed 's/^ *//; s/ .*//')" || fail "the .deb does not depend on $p"
done
contents="$(dpkg-deb -c "$deb" | awk '{print $6}')"
for f in ./opt/billiards/billiards ./opt/billiards/billiards.dll ./opt/billiards/libSkiaSharp.so \
         ./opt/billiards/assets/models/pool-9ft.obj ./opt/billiards/THIRD-PARTY-NOTICES ./usr/bin/billiards \
         ./usr/share/applications/billiards.desktop ./usr/share/icons/hicolor/256x256/apps/billiards.png \
         ./usr/share/doc/billiards/copyright; do
  grep -qx "$f" <<< "$contents" || fail "the .deb lacks $f"   # (no pipe: grep -q would cut it short)
done

tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
dpkg-deb -x "$deb" "$tmp/deb"
grep -qx 'Exec=billiards play' "$tmp/deb/usr/share/applications/billiards.desktop" || fail "the desktop entry does not run billiards play"
grep -q '/opt/billiards/billiards' "$tmp/deb/usr/bin/billiards" || fail "/usr/bin/billiards does not run /opt/billiards/billiards"
[ "$(cd "$tmp" && deb/opt/billiards/billiards --version)" = "billiards $version" ] || fail "the .deb's billiards --version is not 'billiards $version'"

tar -xzf "$out/billiards-$version-linux-x64.tar.gz" -C "$tmp"
cp assets/scenes/eight-ball-break.json "$tmp/scene.json"
[ "$(cd "$tmp" && "billiards-$version-linux-x64/billiards" --version)" = "billiards $version" ] || fail "the tarball's billiards --version is not 'billiards $version'"
(cd "$tmp" && "billiards-$version-linux-x64/billiards" simulate scene.json > result.json) || fail "the tarball's billiards cannot simulate"
grep -q '"billiards-result/1"' "$tmp/result.json" || fail "the tarball's simulate wrote no result"

python3 - "$out/billiards-$version-win-x64.zip" "billiards-$version-win-x64" <<'EOF' || fail "the zip lacks a file the Windows game needs"
import sys, zipfile
names = set(zipfile.ZipFile(sys.argv[1]).namelist())
for f in ['billiards.exe', 'glfw3.dll', 'assimp.dll', 'OpenAL32.dll', 'libSkiaSharp.dll', 'coreclr.dll',
          'THIRD-PARTY-NOTICES', 'LICENSE', 'CHANGELOG.md', 'assets/models/pool-9ft.obj', 'assets/fonts/DejaVuSans-Bold.ttf']:
    assert f'{sys.argv[2]}/{f}' in names, f
EOF
echo "release check: zip, tarball and .deb of $version with their sums, as promised ($(( $(date +%s) - start )) s)"
