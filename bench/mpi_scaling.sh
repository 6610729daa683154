#!/usr/bin/env bash
# quaternia-mpi's scaling on this machine: the default scene at 1920x1080 rendered by
# quaternia (1 and 2 threads) and by quaternia-mpi (1 rank x 1 thread, 2 ranks x 1 thread),
# alternating, RUNS times each; prints the median render seconds (--json) and the median wall
# time of the whole command (MPI start-up included).
# Usage: bench/mpi_scaling.sh [BUILD_DIR] [RUNS] [extra render options...]
set -euo pipefail
build=${1:-build}
runs=${2:-5}
shift $(( $# > 2 ? 2 : $# ))
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
args=(render --width 1920 --height 1080 -o "$out/x.png" --json "$@")
declare -A commands=(
  ["quaternia --threads 1"]="$build/quaternia ${args[*]} --threads 1"
  ["quaternia --threads 2"]="$build/quaternia ${args[*]} --threads 2"
  ["mpirun -np 1, --threads 1"]="mpirun -q -np 1 $build/quaternia-mpi ${args[*]} --threads 1"
  ["mpirun -np 2, --threads 1"]="mpirun -q -np 2 $build/quaternia-mpi ${args[*]} --threads 1"
)
for name in "${!commands[@]}"; do : >"$out/$(echo "$name" | tr -c 'a-z0-9' _)"; done
for ((run = 0; run < runs; ++run)); do
  for name in "${!commands[@]}"; do
    start=$(date +%s%N)
    # The JSON goes to a file and is read afterwards: a reader started beside the command would
    # take a core from it while Python starts.
    ${commands[$name]} >"$out/summary.json"
    end=$(date +%s%N)
    seconds=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["seconds"])' \
      "$out/summary.json")
    echo "$seconds $(( (end - start) / 1000000 ))e-3" >>"$out/$(echo "$name" | tr -c 'a-z0-9' _)"
  done
done
printf '%-28s %14s %14s\n' command "render s" "wall s"
for name in "quaternia --threads 1" "mpirun -np 1, --threads 1" "mpirun -np 2, --threads 1" \
            "quaternia --threads 2"; do
  python3 - "$name" "$out/$(echo "$name" | tr -c 'a-z0-9' _)" <<'PY'
import statistics, sys
rows = [list(map(float, line.split())) for line in open(sys.argv[2])]
print(f"{sys.argv[1]:28s} {statistics.median(r[0] for r in rows):14.3f} {statistics.median(r[1] for r in rows):14.3f}")
PY
done
