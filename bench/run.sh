#!/usr/bin/env bash
# Prints ms per frame and rays/s for fixed, named scenes: medians of several runs of the
# quaternia binary (these machines are shared and noisy), then the Google Benchmark suite.
# Usage: bench/run.sh [runs]   (build first: cmake --build build)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
binary=build/quaternia
[ -x "$binary" ] || { echo "build first: cmake -S . -B build -G Ninja && cmake --build build" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

scene() {  # name, then quaternia render arguments
  local name=$1; shift
  for _ in $(seq "$runs"); do
    "$binary" render "$@" --json -o "$out/frame.png"
  done | python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
ms = statistics.median(r["seconds"] for r in runs) * 1000
rate = statistics.median(r["rays_per_second"] for r in runs)
r = runs[0]
size = "%dx%d" % (r["width"], r["height"])
print("%-24s %-10s %3d spp %9.1f ms/frame %8.3f Mrays/s  (median of %d, %d threads)"
      % (sys.argv[1], size, r["samples"], ms, rate / 1e6, len(runs), r["threads"]))
' "$name"
}

echo "scene                    size       samples   time per frame   speed"
scene default-1080p --width 1920 --height 1080 --set render.samples=1
scene default-preview-360p --width 640 --height 360 --set render.samples=1
scene default-720p-4spp
scene case01-shaded-1080p tests/data/reference/case01_sqr_A.toml --width 1920 --height 1080
if [ -x build/quaternia_bench ]; then
  build/quaternia_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
fi
