#!/usr/bin/env bash
# The throughput report of README "Many simulations at once":
#   tools/random-scenes/throughput.sh [COUNT] [ROUNDS]
# simulate --batch of COUNT seeded random scenes (default 2000, seed 2027) at 1 thread and at
# every core, ROUNDS times each in turn (default 3; the best round of each is reported, as the
# least disturbed by other work on the machine), then self-play games per minute for the
# README's 40-game run on one process and as 2 shards at once (deploy/run-local.sh). Prints the
# load average before and after: the figures mean little on a loaded machine.
set -euo pipefail
count=${1:-2000}; rounds=${2:-3}
root=$(cd "$(dirname "$0")/../.." && pwd)
billiards=${BILLIARDS:-$root/src/Billiards.App/bin/Release/net10.0/billiards}
cores=$(nproc)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
dotnet run --project "$root/tools/random-scenes" -c Release -- "$count" 2027 > "$work/in.jsonl"
echo "before: $(uptime)"
best() { sort -g | tail -1; }
for ((r = 0; r < rounds; r++)); do
  for t in 1 "$cores"; do
    "$billiards" simulate --batch "$work/in.jsonl" --out "$work/out.jsonl" --threads "$t" 2>&1 \
      | tail -1 > "$work/last"
    sed -E 's/.* ([0-9]+) scenes\/s.*/\1/' "$work/last" >> "$work/rate-$t"
    sed -E 's/.*\(([0-9.]+) s of processor time\).*/\1/' "$work/last" >> "$work/cpu-$t"
  done
done
one=$(best < "$work/rate-1"); all=$(best < "$work/rate-$cores")
echo "simulate --batch, $count scenes: 1 thread $one shots/s, $cores threads $all shots/s (best of $rounds; rounds: $(paste -sd' ' "$work/rate-1") / $(paste -sd' ' "$work/rate-$cores")), ratio $(awk -v a="$all" -v b="$one" 'BEGIN { printf "%.2f", a / b }')"
echo "processor seconds of each round: 1 thread $(paste -sd' ' "$work/cpu-1"), $cores threads $(paste -sd' ' "$work/cpu-$cores")"
start=$(date +%s.%N)
"$billiards" selfplay --rules eight-ball --games 40 --levels 3,3 --seed 9 > /dev/null 2>&1
one=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", 40 * 60 / (e - s) }')
start=$(date +%s.%N)
BILLIARDS=$billiards "$root/deploy/run-local.sh" --indexes "$cores" --data "$work/volume" > /dev/null 2>&1
all=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", 40 * 60 / (e - s) }')
echo "selfplay --rules eight-ball --games 40 --levels 3,3 --seed 9: $one games/min in one process, $all games/min as $cores shards at once (run-local.sh)"
echo "after: $(uptime)"
