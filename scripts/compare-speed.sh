#!/usr/bin/env bash
# Proves that a change which is not meant to change speed does not: renders the rows an issue
# names (the default scene, case01, the studio look, bicomplex, octonion and a program formula, at
# 1920x1080 and one sample) with two builds of quaternia, interleaved (before, after, after,
# before, ...: on these shared machines the speed drifts within minutes, so each pair is taken
# back to back), under each instruction set named, and prints per row the median frame time of
# each build (the render's own "seconds" of --json) and the median of the pairs' ratios.
#   scripts/compare-speed.sh BEFORE/quaternia AFTER/quaternia [RUNS [ISA...]]
#                                                  (default: 7 runs, avx2 best)
#   rows=REGEX scripts/compare-speed.sh ...        only the rows whose names match
set -euo pipefail
before=${1:?usage: scripts/compare-speed.sh BEFORE AFTER [RUNS [ISA...]]}
after=${2:?usage: scripts/compare-speed.sh BEFORE AFTER [RUNS [ISA...]]}
runs=${3:-7}
shift $(($# < 3 ? $# : 3))
isas=("$@")
[ ${#isas[@]} -eq 0 ] && isas=(avx2 best)
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

frame=(--width 1920 --height 1080 --set render.samples=1)
# name|quaternia render arguments (before the frame's size and samples: --set takes all the
# values that follow it)
scenes=(
  "default|"
  "case01|$root/bench/scenes/case01_sqr_A_shaded.toml"
  "studio|--preset studio"
  "bicomplex|--set fractal.algebra=\"bicomplex\""
  "octonion|--set fractal.algebra=\"octonion\" --set fractal.c=[-0.2,0.6,0.2,0.2,0.1,0,0.05,0]"
  "program|--set fractal.formula=\"z^2 + 0.1*z + c\""
)

seconds() {  # binary isa arguments...: the render's seconds
  local binary=$1 isa=$2
  shift 2
  "$binary" --isa "$isa" render "$@" "${frame[@]}" --json -o "$work/frame.png" |
    python3 -c 'import json, sys; print(json.load(sys.stdin)["seconds"])'
}

printf '%-10s %-6s %10s %10s %8s\n' row isa before_ms after_ms ratio
for isa in "${isas[@]}"; do
  for entry in "${scenes[@]}"; do
    IFS='|' read -r name arguments <<<"$entry"
    if [ -n "${rows:-}" ] && ! [[ $name =~ $rows ]]; then continue; fi
    eval "args=($arguments)"
    : >"$work/pairs"
    for run in $(seq "$runs"); do
      if [ $((run % 2)) -eq 1 ]; then
        b=$(seconds "$before" "$isa" "${args[@]}")
        a=$(seconds "$after" "$isa" "${args[@]}")
      else
        a=$(seconds "$after" "$isa" "${args[@]}")
        b=$(seconds "$before" "$isa" "${args[@]}")
      fi
      echo "$b $a" >>"$work/pairs"
    done
    python3 - "$name" "$isa" "$work/pairs" <<'EOF'
import statistics, sys
name, isa, path = sys.argv[1:4]
pairs = [tuple(map(float, line.split())) for line in open(path)]
before = statistics.median(b for b, _ in pairs) * 1000
after = statistics.median(a for _, a in pairs) * 1000
ratio = statistics.median(a / b for b, a in pairs)
print(f"{name:<10} {isa:<6} {before:10.1f} {after:10.1f} {ratio:8.3f}")
EOF
  done
done
