#!/usr/bin/env bash
# The computer player under execution noise (docs/computer-player.md#execution-noise): for each
# noise level K in 0, 1 and 5, level 5 playing for the noise (player 0) against level 5 blind to it
# (player 1) at 8-ball, GAMES games (the break alternating) in two shards side by side with one
# search thread each, merged; then the odd games again, the racks the blind planner broke there,
# played by the planner for the noise on both sides (shards 1/4 and 3/4 side by side), so that the
# break-and-run rate counts every rack of the run; then `billiards report ai` writes docs/ai/ai.md
# and its plot, and the summaries go to docs/ai/runs.
# Usage: tools/ai/noise-report.sh [GAMES] [SEED] [OUT] [SCALES] [PARTS]
#   (defaults: 500 games, seed 39, docs/ai, the scales "0 1 5", the parts "runs breaks"; e.g.
#   SCALES "1" runs 1x alone, PARTS "breaks" plays only the odd games again, next to the runs'
#   summaries already in out/ai-runs)
# The full size (500 games a level) took 3.3 CPU-hours (1.9 hours on two cores); the run files stay in out/ai-runs.
set -euo pipefail
cd "$(dirname "$0")/../.."
games="${1:-500}"
seed="${2:-39}"
out="${3:-docs/ai}"
scales="${4:-0 1 5}"
parts="${5:-runs breaks}"
runs=out/ai-runs
dotnet build src/Billiards.App -c Release -v q -nologo >/dev/null
bin=src/Billiards.App/bin/Release/net10.0/billiards
mkdir -p "$runs" "$out/runs"
# play K PLANNERS PREFIX SHARD...: the run's shards side by side, one search thread each, each verified.
play() {
  local k=$1 planners=$2 prefix=$3 start
  shift 3
  start=$(date +%s)
  for shard in "$@"; do
    local name="$runs/$prefix$k-${shard%/*}"
    "$bin" selfplay --rules eight-ball --games "$games" --levels 5,5 --seed "$seed" \
      --noise "fastfiz:$k" --planners "$planners" --threads 1 --shard "$shard" \
      --out "$name.jsonl" --summary "$name.json" 2> "$name.log" &
  done
  wait
  for shard in "$@"; do
    "$bin" replay "$runs/$prefix$k-${shard%/*}.jsonl" --verify > /dev/null
  done
  echo "fastfiz:$k, $planners, shards $*: $(( $(date +%s) - start )) s"
}
for k in $scales; do
  if [[ " $parts " == *" runs "* ]]; then
    play "$k" noise,blind k 0/2 1/2
    "$bin" selfplay --merge "$runs/k$k-0.json" "$runs/k$k-1.json" --summary "$runs/k$k.json"
  fi
  if [[ " $parts " == *" breaks "* ]]; then
    play "$k" noise,noise b 1/4 3/4
  fi
done
summaries=() breaks=()
for k in $(ls "$runs" | sed -n 's/^k\([0-9.]*\)\.json$/\1/p' | sort -n); do
  if [[ -f "$runs/k$k.json" ]]; then
    summaries+=("$runs/k$k.json")
    cp "$runs/k$k.json" "$out/runs/k$k.json"
    for i in 1 3; do
      if [[ -f "$runs/b$k-$i.json" ]]; then
        breaks+=("$runs/b$k-$i.json")
        cp "$runs/b$k-$i.json" "$out/runs/b$k-$i.json"
      fi
    done
  fi
done
"$bin" report ai "${summaries[@]}" ${breaks:+--breaks "${breaks[@]}"} --out "$out"
