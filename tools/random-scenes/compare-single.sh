#!/usr/bin/env bash
# Checks that `simulate --batch` gives, line for line, what single `simulate` runs print:
#   [JOBS=J] tools/random-scenes/compare-single.sh COUNT SEED [THREADS]
# COUNT seeded random scenes go through one batch run and through COUNT single runs (one process
# each); every result is compared byte for byte once white space is taken out (the batch writes a
# result on one line, a single run indents it) and stats.wall_ms (a measurement) is blanked.
set -euo pipefail
count=${1:?COUNT}; seed=${2:?SEED}; threads=${3:-$(nproc)}
root=$(cd "$(dirname "$0")/../.." && pwd)
billiards=${BILLIARDS:-$root/src/Billiards.App/bin/Release/net10.0/billiards}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
dotnet run --project "$root/tools/random-scenes" -c Release -- "$count" "$seed" > "$work/in.jsonl"
"$billiards" simulate --batch "$work/in.jsonl" --out "$work/batch.jsonl" --threads "$threads"
mkdir "$work/scenes" "$work/single"
k=0
while IFS= read -r line; do
  k=$((k + 1))
  printf '%s\n' "$line" > "$work/scenes/$k.json"
done < "$work/in.jsonl"
# The single runs, one process each, a core's worth at a time (JOBS; a run's result does not
# depend on what else runs).
seq 1 "$count" | xargs -P "${JOBS:-$(nproc)}" -I{} "$billiards" simulate "$work/scenes/{}.json" --out "$work/single/{}.json"
python3 - "$work" "$count" <<'PY'
import re, sys
work, count = sys.argv[1], int(sys.argv[2])
def compact(text):
    out, in_string, escape = [], False, False
    for c in text:
        if in_string:
            out.append(c)
            if escape: escape = False
            elif c == '\\': escape = True
            elif c == '"': in_string = False
        elif c == '"':
            in_string = True; out.append(c)
        elif not c.isspace():
            out.append(c)
    return re.sub(r'"wall_ms":[-0-9.eE+]+', '"wall_ms":_', ''.join(out))
batch = open(f"{work}/batch.jsonl", encoding="utf-8").read().split("\n")[:-1]
assert len(batch) == count, f"{len(batch)} batch lines for {count} scenes"
same = 0
for k in range(1, count + 1):
    single = compact(open(f"{work}/single/{k}.json", encoding="utf-8").read())
    if compact(batch[k - 1]) == single:
        same += 1
    else:
        print(f"scene {k}: the batch line differs from the single run", file=sys.stderr)
print(f"{same} of {count} batch results equal the single runs byte for byte (stats.wall_ms aside)")
sys.exit(0 if same == count else 1)
PY
