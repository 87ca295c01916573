#!/usr/bin/env bash
# The level-5 decision on today's Billiards.Core and, side by side in one BenchmarkDotNet run, on
# older Cores (tools/bench/baseline-core.sh builds each): by default 03cad24, the commit the turn
# controller was built on, and c4c8cca, the turn controller's branch before it merged with the
# physics and carom work. One job of TurnControllerBenchmarks per build of the benchmark project.
# Keeps its table in tests/Billiards.Benchmarks/results/ (the run's logs stay in build/bench/).
# Usage: tools/bench/turn-controller.sh [COMMIT...]
set -euo pipefail
cd "$(dirname "$0")/../.."
commits=("$@")
[ ${#commits[@]} -gt 0 ] || commits=(03cad24 c4c8cca)
BILLIARDS_BASELINE_CORE=""
for c in "${commits[@]}"; do
  BILLIARDS_BASELINE_CORE+="$c=$(bash tools/bench/baseline-core.sh "$c");"
done
export BILLIARDS_BASELINE_CORE
dotnet run -c Release --project tests/Billiards.Benchmarks -- --filter '*TurnControllerBenchmarks*' \
  --artifacts build/bench/turn-controller
cp build/bench/turn-controller/results/Billiards.Benchmarks.TurnControllerBenchmarks-report-github.md tests/Billiards.Benchmarks/results/
