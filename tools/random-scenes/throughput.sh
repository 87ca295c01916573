#!/usr/bin/env bash
# The throughput report of README "Many simulations at once":
#   tools/random-scenes/throughput.sh [COUNT] [ROUNDS] [--no-selfplay]
# simulate --batch of COUNT seeded random scenes (default 8000, seed 2027) at 1 thread and at
# every core, ROUNDS times each in turn (default 3), then self-play games per minute for the
# README's 40-game run in one process and as one shard a core at once (deploy/run-local.sh: the
# manifest's pods, each searching on one thread).
#
# Two measures of the batch:
# - shots per second, wall clock, the best round of each thread count (the least disturbed by
#   other work), and their ratio: the figure that matters, on a quiet machine;
# - processor milliseconds a scene (every thread of the process, from the batch's own last
#   line), the median round of each: on a machine shared with other work the wall clock says
#   little, but if 2 threads cost the same processor time a scene as 1, nothing in the process
#   makes them wait for or slow each other, and on 2 free cores they give about twice the shots
#   per second (less the start, which runs on one thread).
# Prints the load average before and after, and the allocation and collections of the batch.
# Environment: BILLIARDS (the executable), and anything the runtime reads (e.g.
# DOTNET_TC_QuickJit=1 to measure the runtime's default quick first tier instead of the App's).
set -euo pipefail
count=8000; rounds=3; selfplay=1; positional=0
for arg in "$@"; do
  case "$arg" in
    --no-selfplay) selfplay=0 ;;
    *) if [ $positional -eq 0 ]; then count=$arg; else rounds=$arg; fi; positional=$((positional + 1)) ;;
  esac
done
root=$(cd "$(dirname "$0")/../.." && pwd)
billiards=${BILLIARDS:-$root/src/Billiards.App/bin/Release/net10.0/billiards}
cores=$(nproc)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
dotnet run --project "$root/tools/random-scenes" -c Release -- "$count" 2027 > "$work/in.jsonl"
echo "before: $(uptime)"
for ((r = 0; r < rounds; r++)); do
  for t in 1 "$cores"; do
    "$billiards" simulate --batch "$work/in.jsonl" --out "$work/out.jsonl" --threads "$t" 2> "$work/err"
    tail -1 "$work/err" > "$work/last"
    sed -E 's/.* ([0-9]+) scenes\/s.*/\1/' "$work/last" >> "$work/rate-$t"
    sed -E 's/.*\(([0-9.]+) s of processor time.*/\1/' "$work/last" \
      | awk -v n="$count" '{ printf "%.3f\n", $1 * 1000 / n }' >> "$work/cpu-$t"
    tail -1 "$work/last" | sed -E 's/.*processor time; (.*)\)$/\1/' > "$work/memory-$t"
  done
done
best() { sort -g | tail -1; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
one=$(best < "$work/rate-1"); all=$(best < "$work/rate-$cores")
cpu1=$(median < "$work/cpu-1"); cpuN=$(median < "$work/cpu-$cores")
echo "simulate --batch, $count scenes: 1 thread $one shots/s, $cores threads $all shots/s (best of $rounds; rounds: $(paste -sd' ' "$work/rate-1") / $(paste -sd' ' "$work/rate-$cores")), ratio $(awk -v a="$all" -v b="$one" 'BEGIN { printf "%.2f", a / b }')"
echo "processor time a scene (median of $rounds): 1 thread $cpu1 ms, $cores threads $cpuN ms (rounds: $(paste -sd' ' "$work/cpu-1") / $(paste -sd' ' "$work/cpu-$cores")), $cores threads cost $(awk -v a="$cpuN" -v b="$cpu1" 'BEGIN { printf "%.2f", a / b }') times the processor time of 1"
echo "allocation: 1 thread $(cat "$work/memory-1"); $cores threads $(cat "$work/memory-$cores")"
if [ "$selfplay" -eq 1 ]; then
  game=(selfplay --rules eight-ball --games 40 --levels 3,3 --seed 9)
  start=$(date +%s.%N)
  /usr/bin/time -f "%U %S" -o "$work/time" "$billiards" "${game[@]}" > /dev/null 2>&1
  end=$(date +%s.%N)
  read -r user sys < "$work/time"
  one=$(awk -v s="$start" -v e="$end" 'BEGIN { printf "%.1f", 40 * 60 / (e - s) }')
  busy=$(awk -v s="$start" -v e="$end" -v u="$user" -v k="$sys" 'BEGIN { printf "%.2f", (u + k) / (e - s) }')
  cpu=$(awk -v u="$user" -v k="$sys" 'BEGIN { printf "%.2f", u + k }')
  start=$(date +%s.%N)
  BILLIARDS=$billiards "$root/deploy/run-local.sh" --indexes "$cores" --data "$work/volume" > /dev/null 2>&1
  all=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN { printf "%.1f", 40 * 60 / (e - s) }')
  echo "${game[*]}: $one games/min in one process ($cpu processor s, $busy cores busy on average: its search runs on every core), $all games/min as $cores shards at once (run-local.sh: the manifest's pods, one search thread each)"
fi
echo "after: $(uptime)"
