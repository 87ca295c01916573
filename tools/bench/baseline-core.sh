#!/usr/bin/env bash
# Builds Billiards.Core as it stood at COMMIT into build/baseline-core/COMMIT/ (git-ignored) and
# prints the path of its Billiards.Core.dll, for a benchmark job run side by side against today's
# Core (TurnControllerBenchmarks; tools/bench/turn-controller.sh runs it).
# Usage: tools/bench/baseline-core.sh [COMMIT]   (default 03cad24, the commit the turn controller was built on)
set -euo pipefail
cd "$(dirname "$0")/../.."
commit="$(git rev-parse --short=12 "${1:-03cad24}^{commit}")"
dir="$(pwd)/build/baseline-core/$commit"
if [ ! -f "$dir/bin/Billiards.Core.dll" ]; then
  rm -rf "$dir"
  mkdir -p "$dir/src"
  git archive "$commit" Directory.Build.props Directory.Packages.props global.json nuget.config src/Billiards.Core \
    | tar -x -C "$dir/src"
  dotnet build "$dir/src/src/Billiards.Core" -c Release -o "$dir/bin" -v q -nologo >"$dir/build.log" 2>&1 \
    || { tail -n 20 "$dir/build.log" >&2; echo "baseline-core: Billiards.Core at $commit did not build" >&2; exit 1; }
fi
echo "$dir/bin/Billiards.Core.dll"
