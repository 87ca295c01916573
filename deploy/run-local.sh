#!/usr/bin/env bash
# Runs the Kubernetes job of deploy/kubernetes as local processes: the pods of
# selfplay-job.yaml (one process per index, all at once, each with the manifest's environment,
# JOB_COMPLETION_INDEX and the manifest's own command), then the pod of merge-job.yaml.
#
#   deploy/run-local.sh [--indexes N] [--data DIR] [--set NAME=VALUE ...]
#
# --indexes N   the shard count (the manifest's completions and its N; default: the manifest's)
# --data DIR    the folder that stands for the shared volume (default: a new temporary folder);
#               DATA, the volume's mount path in the pods, is set to it
# --set NAME=VALUE  overrides one of the manifest's environment variables (e.g. --set GAMES=8)
# BILLIARDS     the command that stands for the image's billiards (default: this repository's
#               Release build, src/Billiards.App/bin/Release/net10.0/billiards, built if missing)
#
# Prints the merged summary; DIR then holds what the volume would: summary-K.json and
# games-K.jsonl of each shard, summary.json and games.jsonl of the whole run.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
shard_manifest=$here/kubernetes/selfplay-job.yaml
merge_manifest=$here/kubernetes/merge-job.yaml

# The container's "args: - |" script of a manifest (each manifest has one container), dedented.
script_of() {
  awk '
    /^ *args:$/ { in_args = 1; next }
    in_args && /^ *- \|$/ { match($0, /^ */); indent = RLENGTH; in_block = 1; in_args = 0; next }
    in_block {
      match($0, /^ */)
      if ($0 !~ /^ *$/ && RLENGTH <= indent) { exit }
      print substr($0, indent + 3)
    }' "$1"
}

# The container's environment of a manifest as NAME=VALUE lines ("- name: X" then "value: Y").
env_of() {
  awk '
    /^ *- name: / { name = $3; next }
    name != "" && /^ *value: / { v = $0; sub(/^ *value: */, "", v); gsub(/^"|"$/, "", v); print name "=" v }
    { name = "" }' "$1"
}

indexes=""; data=""; sets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --indexes) indexes=${2:?--indexes N}; shift 2 ;;
    --data) data=${2:?--data DIR}; shift 2 ;;
    --set) sets+=("${2:?--set NAME=VALUE}"); shift 2 ;;
    *) echo "run-local.sh: unknown argument $1 (see the comment at the top)" >&2; exit 2 ;;
  esac
done
if [ -z "$indexes" ]; then
  indexes=$(awk '/^ *completions: / { print $2; exit }' "$shard_manifest")
fi
case "$indexes" in ''|*[!0-9]*|0) echo "run-local.sh: --indexes $indexes: expected a whole number >= 1" >&2; exit 2 ;; esac
if [ -z "$data" ]; then
  data=$(mktemp -d)
fi
mkdir -p "$data"
data=$(cd "$data" && pwd)

# billiards on the PATH, as in the image.
bin=$(mktemp -d); trap 'rm -rf "$bin"' EXIT
if [ -z "${BILLIARDS:-}" ]; then
  BILLIARDS=$root/src/Billiards.App/bin/Release/net10.0/billiards
  [ -x "$BILLIARDS" ] || dotnet build "$root/src/Billiards.App" -c Release >&2
fi
printf '#!/bin/sh\nexec %s "$@"\n' "$BILLIARDS" > "$bin/billiards"
chmod +x "$bin/billiards"

# The environment of a manifest's pod: its env (with N and DATA as this run has them, and the
# --set overrides) and nothing of this shell's but PATH and HOME.
pod_env() {
  local line
  while IFS= read -r line; do
    case "$line" in N=*) line="N=$indexes" ;; DATA=*) line="DATA=$data" ;; esac
    for s in "${sets[@]+"${sets[@]}"}"; do
      [ "${s%%=*}" = "${line%%=*}" ] && line=$s
    done
    printf '%s\n' "$line"
  done < <(env_of "$1")
}

shard_script=$(script_of "$shard_manifest")
mapfile -t shard_env < <(pod_env "$shard_manifest")
pids=()
for ((k = 0; k < indexes; k++)); do
  env -i PATH="$bin:$PATH" HOME="${HOME:-/tmp}" "${shard_env[@]}" JOB_COMPLETION_INDEX=$k /bin/sh -c "$shard_script" &
  pids+=($!)
done
failed=0
for k in "${!pids[@]}"; do
  if ! wait "${pids[$k]}"; then
    echo "run-local.sh: index $k failed" >&2
    failed=1
  fi
done
[ "$failed" = 0 ] || exit 1

merge_script=$(script_of "$merge_manifest")
mapfile -t merge_env < <(pod_env "$merge_manifest")
env -i PATH="$bin:$PATH" HOME="${HOME:-/tmp}" "${merge_env[@]}" /bin/sh -c "$merge_script"
cat "$data/summary.json"
