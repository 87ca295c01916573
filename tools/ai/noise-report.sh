#!/usr/bin/env bash
# The computer player under execution noise (docs/computer-player.md#execution-noise): for each
# noise level K in 0, 1 and 5, level 5 playing for the noise (player 0) against level 5 blind to it
# (player 1) at 8-ball, GAMES games (the break alternating) in two shards side by side with one
# search thread each, merged; then `billiards report ai` writes docs/ai/ai.md and its plot.
# Usage: tools/ai/noise-report.sh [GAMES] [SEED] [OUT] [SCALES]
#   (defaults: 500 games, seed 39, docs/ai, the scales "0 1 5"; e.g. SCALES "1" runs 1x alone)
# The full size (500 games a level) takes about 3 CPU-hours; the run files stay in out/ai-runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
games="${1:-500}"
seed="${2:-39}"
out="${3:-docs/ai}"
scales="${4:-0 1 5}"
runs=out/ai-runs
dotnet build src/Billiards.App -c Release -v q -nologo >/dev/null
bin=src/Billiards.App/bin/Release/net10.0/billiards
mkdir -p "$runs"
summaries=()
for k in $scales; do
  start=$(date +%s)
  for i in 0 1; do
    "$bin" selfplay --rules eight-ball --games "$games" --levels 5,5 --seed "$seed" \
      --noise "fastfiz:$k" --planners noise,blind --threads 1 --shard "$i/2" \
      --out "$runs/k$k-$i.jsonl" --summary "$runs/k$k-$i.json" 2> "$runs/k$k-$i.log" &
  done
  wait
  "$bin" selfplay --merge "$runs/k$k-0.json" "$runs/k$k-1.json" --summary "$runs/k$k.json"
  "$bin" replay "$runs/k$k-0.jsonl" --verify > /dev/null
  "$bin" replay "$runs/k$k-1.jsonl" --verify > /dev/null
  echo "fastfiz:$k, $games games: $(( $(date +%s) - start )) s"
  summaries+=("$runs/k$k.json")
done
"$bin" report ai "${summaries[@]}" --out "$out"
