#!/usr/bin/env bash
# Prints ms per frame and rays/s for fixed, named scenes: medians of several runs of the
# quaternia binary (these machines are shared and noisy), then the Google Benchmark suite.
# The tables also go to a results file, bench/results/run-DATE-ISA.md (bench/results/README.md),
# headed by the machine, the lanes' instruction set, the date and the commit (bench/machine.py).
# Usage: bench/run.sh [runs]   (build first: cmake --build build)
#        rows=REGEX bench/run.sh [runs]   only the frame rows whose names match (no films, meshes
#        or Google Benchmark suite), e.g. rows=algebra bench/run.sh 5; the materials' rows
#        (rows='reflection|look|environment|glow|three') pair each run with one of the plain frame
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-5}
binary=build/quaternia
[ -x "$binary" ] || { echo "build first: cmake -S . -B build -G Ninja && cmake --build build" >&2; exit 2; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
python3 bench/machine.py "$binary" run "bench/run.sh" "${rows:+rows='$rows' }bench/run.sh $runs" \
  > "$out/head.md"
report=$(head -n 1 "$out/head.md")
{ tail -n +2 "$out/head.md"; echo '```text'; } > "$report"

scene() {  # name, then quaternia render arguments; isa=avx2 scene ... caps the lanes (--isa)
  local name=$1; shift
  if [ -n "${rows:-}" ] && ! [[ $name =~ $rows ]]; then return; fi
  # The summaries go to a file and are read after the runs: a reader started beside them (a
  # pipe into python3) would take the other core while the first render runs.
  : > "$out/runs.jsonl"
  for _ in $(seq "$runs"); do
    "$binary" --isa "${isa:-best}" render "$@" --json -o "$out/frame.png" >> "$out/runs.jsonl"
  done
  python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
ms = statistics.median(r["seconds"] for r in runs) * 1000
rate = statistics.median(r["rays_per_second"] for r in runs)
r = runs[0]
size = "%dx%d" % (r["width"], r["height"])
print("%-28s %-10s %8.1f ms %6.1f fps %8.2f Mrays/s  %-7s lanes %3.0f%%  steps/ray %5.1f  iter/ray %5.0f  shading/hit %4.1f  (median of %d, %d threads)"
      % (sys.argv[1], size, ms, 1000 / ms, rate / 1e6, r["engine"], 100 * r["lane_utilisation"],
         r["march_steps"] / r["rays"], r["iterations"] / r["rays"],
         r["shading_estimates"] / max(1, r["hits"]), len(runs), r["threads"]))
' "$name" < "$out/runs.jsonl"
}

# The default benchmark scene: the default scene at 1920x1080, 1 sample, key light with soft
# shadows and ambient occlusion (the scene's defaults). Frame time is the render itself (the
# "seconds" of --json), not the process start or the PNG encoding.
one_spp=(--set render.samples=1)
tables() {  # everything printed from here on, into the results file too
echo "scene                        size         time     rate     speed    path    lanes   counters"
scene default-1080p --width 1920 --height 1080 "${one_spp[@]}"
# 16 samples per pixel, every one in every pixel and adaptively (render.adaptive: the rest of
# the samples only where a pixel's first samples and its neighbours' disagree).
scene default-1080p-16spp-uniform --width 1920 --height 1080 --set render.samples=16 \
  --set render.adaptive=false
scene default-1080p-16spp-adaptive --width 1920 --height 1080 --set render.samples=16 \
  --set render.adaptive=true
# Formulas that are not z^2 + c (issue 17), the default scene otherwise: a real form (float
# three-number lanes), a two-sided one (a compiled program on lane quaternions) and z^3 + c with
# c = -0.5 + 0.5i; then the same on AVX2 (quaternia --isa avx2), beside z^2 + c on AVX2, which is
# what the issue's goals compare against. In-process: build/quaternia_bench
# --benchmark_filter=RenderFormula.
for target in best avx2; do
  if [ "$target" = avx2 ]; then
    isa=avx2 scene default-1080p-avx2 --width 1920 --height 1080 "${one_spp[@]}"
  fi
  isa=$target scene "formula-z2+0.1z-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}" \
    --set 'fractal.formula=z^2 + 0.1*z + c'
  isa=$target scene "formula-two-sided-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}" \
    --set 'fractal.formula=(1+0.2i) z (1-0.1k) z + c'
  isa=$target scene "formula-z3-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}" \
    --set 'fractal.formula=z^3 + c' --set 'fractal.c=[-0.5, 0.5, 0, 0]'
done
scene default-1080p-1-thread --width 1920 --height 1080 "${one_spp[@]}" --threads 1
scene default-1080p-double --width 1920 --height 1080 "${one_spp[@]}" --set render.precision=double
scene default-1080p-scalar --width 1920 --height 1080 "${one_spp[@]}" --set render.engine=scalar
scene default-preview-360p --width 640 --height 360 "${one_spp[@]}"
scene default-720p-4spp
scene case01-shaded-1080p bench/scenes/case01_sqr_A_shaded.toml
isa=avx2 scene case01-shaded-1080p-avx2 bench/scenes/case01_sqr_A_shaded.toml
# Other algebras (issue 16), the default scene otherwise, side by side with z^2 + c above:
# bicomplex z^2 + c (the two duplex components in the lanes), octonion z^2 + c with c outside the
# quaternion half on the default slice (an isometry into H) and on a slice whose directions
# orthogonal to 1 and Im c span four dimensions (the fold's length in the lanes), each on the
# best ISA and on AVX2; then the fixed-step algebras (scalar reference) at 640x360 (the
# biquaternion's c with an ih part: with c in H it is the quaternion set, in the lanes).
octonion=(--set 'fractal.algebra="octonion"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0.1, 0, 0.05, 0]')
folded=("${octonion[@]}" --set 'slice.axes=[[1,0,0,0,0,0,0,0],[0,1,0,0.2,0,0,0,0],[0,0,0,0,0,0,1,0.3]]')
for target in best avx2; do
  isa=$target scene "algebra-quaternion-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}"
  isa=$target scene "algebra-bicomplex-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}" \
    --set 'fractal.algebra="bicomplex"'
  isa=$target scene "algebra-octonion-1080p-$target" --width 1920 --height 1080 "${one_spp[@]}" \
    "${octonion[@]}"
  isa=$target scene "algebra-octonion-folded-1080p-$target" --width 1920 --height 1080 \
    "${one_spp[@]}" "${folded[@]}"
done
scene algebra-coquaternion-360p --width 640 --height 360 "${one_spp[@]}" \
  --set 'fractal.algebra="coquaternion"'
scene algebra-biquaternion-360p --width 640 --height 360 "${one_spp[@]}" \
  --set 'fractal.algebra="biquaternion"' --set 'fractal.c=[-0.2, 0.6, 0.2, 0.2, 0, 0.1, 0, 0]'
# Materials and lights (issue 20), 1 sample at 1080p, each against the plain frame on the same
# ISA (the goals: a reflective bounce with the ground at most 2x the plain frame, glass at most
# 4x): the default scene with the ground and reflectivity 0.6, one bounce; the looks (presets
# studio, chrome, glass: ground, extra light, mirror, glass); the glow; two extra lights. Each
# run of a row is paired with a run of the plain frame just before it, and the row's ratio is
# the median of the pairs' ratios: on these shared machines the speed drifts by 30% within
# minutes, which a ratio of two medians taken minutes apart would carry.
paired() {  # name, then quaternia render arguments of the row; isa=... as for scene
  local name=$1; shift
  if [ -n "${rows:-}" ] && ! [[ $name =~ $rows ]]; then return; fi
  : > "$out/pairs.jsonl"
  for _ in $(seq "$runs"); do
    "$binary" --isa "${isa:-best}" render --width 1920 --height 1080 "${one_spp[@]}" --json \
      -o "$out/frame.png" >> "$out/pairs.jsonl"
    "$binary" --isa "${isa:-best}" render --width 1920 --height 1080 "${one_spp[@]}" "$@" \
      --json -o "$out/frame.png" >> "$out/pairs.jsonl"
  done
  python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
plain, row = runs[0::2], runs[1::2]
ms = statistics.median(r["seconds"] for r in row) * 1000
plain_ms = statistics.median(r["seconds"] for r in plain) * 1000
ratio = statistics.median(b["seconds"] / a["seconds"] for a, b in zip(plain, row))
r = row[0]
print("%-28s %-10s %8.1f ms %5.2fx plain (plain %6.1f ms) %8.2f Mrays/s  %-7s steps/ray %5.1f  iter/ray %5.0f  (median of %d pairs, %d threads)"
      % (sys.argv[1], "%dx%d" % (r["width"], r["height"]), ms, ratio, plain_ms,
         statistics.median(x["rays_per_second"] for x in row) / 1e6, r["engine"],
         r["march_steps"] / r["rays"], r["iterations"] / r["rays"], len(row), r["threads"]))
' "$name" < "$out/pairs.jsonl"
}
for target in best avx2; do
  isa=$target paired "reflection-ground-1080p-$target" --set ground.enabled=true \
    --set material.reflectivity=0.6 --set material.max_depth=1
  for look in studio chrome glass sunset; do
    isa=$target paired "look-$look-1080p-$target" --preset "$look"
  done
  # The environment (issue 39; the goals: chrome with a map at most 2x the plain frame, the
  # map's diffuse light with occlusion by 4 shadow rays per hit at most 3x).
  isa=$target paired "environment-chrome-map-1080p-$target" --preset chrome \
    --set 'environment.map="data/environments/studio.hdr"'
  isa=$target paired "environment-light-1080p-$target" --set environment.enabled=true \
    --set 'environment.map="data/environments/studio.hdr"' --set environment.samples=4
  isa=$target paired "glow-1080p-$target" --set shading.glow_intensity=1
  isa=$target paired "three-lights-1080p-$target" --set light1.enabled=true \
    --set light2.enabled=true --set light2.kind=directional
  # Every algebra at 1080p against quaternion z^2 + c (issue 42; the goals: coquaternions and
  # biquaternions at most 10x): the coquaternion default scene (fixed steps crossing proven
  # empty space, scalar), and the biquaternion default scene (c in H: the quaternion set, lanes).
  isa=$target paired "algebra-coquaternion-1080p-$target" --set 'fractal.algebra="coquaternion"'
  isa=$target paired "algebra-biquaternion-half-1080p-$target" \
    --set 'fractal.algebra="biquaternion"'
  # Bicomplex functions (issue 42's goal: at most 5x): fixed steps, skipping the samples within
  # the duplex components' certified escape maps' clearance (fractal/duplex_escape_map.h); the
  # maps are built in the frame's time.
  isa=$target paired "algebra-bicomplex-sin-1080p-$target" --set 'fractal.algebra="bicomplex"' \
    --set 'fractal.formula="sin(z) + c"'
  isa=$target paired "algebra-bicomplex-exp-1080p-$target" --set 'fractal.algebra="bicomplex"' \
    --set 'fractal.formula="exp(z) + c"'
  # Ten general polynomials of degrees 2 to 5, one- and two-sided, several terms (issue 42; the
  # goals: median at most 2.5x the quaternion z^2 + c frame, none above 4x), the default scene
  # otherwise. The list is fixed, the default c for every formula.
  polynomials=('z^2 + 0.1*z + c' 'i z^2 j + c' '(1+0.2i) z (1-0.1k) z + 0.1j z + c' 'z^3 + c'
    'z^3 + 0.2j z^2 + c' '(1+0.1j) z^3 - 0.3i z + c' 'z^4 + c' 'z^4 - 0.2 z^2 + 0.1k z + c'
    'z^5 + c' 'z j z^4 + 0.1 z^2 + c')
  for n in "${!polynomials[@]}"; do
    isa=$target paired "polynomial-$((n + 1))-1080p-$target" \
      --set "fractal.formula=${polynomials[$n]}"
  done
done
# Certified pictures (issue 38; the goals: a certificate at 640x360 in at most 20x the time of
# the picture itself, undecided pixels at most 5%): each run renders the scene as it is (its
# own samples) and certifies it (render --certify); the row's ratio is the median of the runs'
# certificate / picture ratios, the certificate being scalar (the picture on the ISA named).
certified() {  # name, then quaternia render arguments; isa=... as for scene
  local name=$1; shift
  if [ -n "${rows:-}" ] && ! [[ $name =~ $rows ]]; then return; fi
  : > "$out/certified.jsonl"
  for _ in $(seq "$runs"); do
    "$binary" --isa "${isa:-best}" render --width 640 --height 360 "$@" --json \
      --certify "$out/classes.png" -o "$out/frame.png" >> "$out/certified.jsonl"
  done
  python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
picture = statistics.median(r["seconds"] for r in runs) * 1000
certificate = statistics.median(r["certificate"]["seconds"] for r in runs) * 1000
ratio = statistics.median(r["certificate"]["seconds"] / r["seconds"] for r in runs)
r = runs[0]
c = r["certificate"]
print("%-32s %-10s picture %7.1f ms (%d spp, %-7s) certificate %8.1f ms %5.1fx  undecided %5.2f%% hit %5.1f%% missed %5.1f%%  (median of %d, %d threads)"
      % (sys.argv[1], "%dx%d" % (r["width"], r["height"]), picture, r["samples"], r["engine"],
         certificate, ratio, 100 * c["undecided_fraction"],
         100 * c["hit"] / (r["width"] * r["height"]), 100 * c["missed"] / (r["width"] * r["height"]),
         len(runs), r["threads"]))
' "$name" < "$out/certified.jsonl"
}
for target in best avx2; do
  isa=$target certified "certify-default-360p-$target"
done
for preset in studio rabbit dendrite basilica cubic two-sided bicomplex coquaternion \
  biquaternion octonion; do
  certified "certify-$preset-360p" --preset "$preset"
done
# True sets (issue 40; the goals: the basilica and the rabbit at 4096^2 in at most 15 s with an
# undecided band at most 3 px wide, 16384^2 in at most 6 minutes, the rabbit's quaternion twin at
# 512^3 cells in at most 10 minutes and 4 GB): `quaternia certify` runs, each timed whole (the
# process, PNG or cells file written) with its peak resident memory; medians of the runs given.
trueset() {  # name, runs, then quaternia certify arguments
  local name=$1 count=$2; shift 2
  if [ -n "${rows:-}" ] && ! [[ $name =~ $rows ]]; then return; fi
  python3 - "$name" "$count" "$binary" "$@" <<'PY'
import json, resource, statistics, subprocess, sys, time
name, count, binary, args = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
runs, walls = [], []
for _ in range(count):
    start = time.monotonic()
    done = subprocess.run([binary, "certify", *args, "--json"], capture_output=True, text=True, check=True)
    walls.append(time.monotonic() - start)
    runs.append(json.loads(done.stdout))
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024 / 1024
r = runs[0]
if r["space"] == "plane":
    p, b = r["pixels"], r["undecided_band_pixels"]
    what = "%dx%d  undecided %.3f%%  band median %d p99 %d max %d px  inside %.2f%%" % (
        r["width"], r["height"], 100 * p["undecided_fraction"], b["median"], b["p99"], b["max"],
        100 * p["inside"] / (r["width"] * r["height"]))
else:
    cells = sum(g["outside"] + g["inside"] + g["undecided"] for g in r["grids"])
    inside = sum(g["inside"] for g in r["grids"])
    undecided = sum(g["undecided_volume"] for g in r["grids"]) / sum(
        g["outside_volume"] + g["inside_volume"] + g["undecided_volume"] for g in r["grids"])
    what = "%s %d cells/axis  %d leaf cells  inside %d  undecided volume %.3f%%  file %.1f MB" % (
        r["space"], r["cells_per_axis"], cells, inside, 100 * undecided, r["bytes"] / 1e6)
print("%-30s %8.2f s whole (%6.2f s cell mapping)  peak %5.2f GB  %s  (median of %d, %d threads)"
      % (name, statistics.median(walls), statistics.median(x["seconds"] for x in runs), peak,
         what, len(runs), r["threads"]))
PY
}
julia() { echo "--set" "fractal.c=[$1,$2,0,0]" "--set" "plane.width=$3"; }
trueset "trueset-basilica-4096" 3 $(julia -1 0 3.4) --width 4096 --height 4096 -o "$out/t.png"
trueset "trueset-rabbit-4096" 3 $(julia -0.122561 0.744862 3.2) --width 4096 --height 4096 \
  -o "$out/t.png"
trueset "trueset-basilica-16384" 1 $(julia -1 0 3.4) --width 16384 --height 16384 -o "$out/t.png"
trueset "trueset-rabbit-16384" 1 $(julia -0.122561 0.744862 3.2) --width 16384 --height 16384 \
  -o "$out/t.png"
trueset "trueset-rabbit-twin-512" 1 --set "fractal.c=[-0.122561,0.744862,0,0]" --resolution 512 \
  -o "$out/twin.qcells"
trueset "trueset-default-256" 1 --resolution 256 -o "$out/default.qcells"
trueset "trueset-bicomplex-4096" 1 --preset bicomplex --resolution 4096 -o "$out/bicomplex.qcells"
# The picture's certificate against K (render.certified) beside the one against K_N.
if [ -z "${rows:-}" ] || [[ trueset-render-rabbit-twin-360p =~ $rows ]]; then
  [ -f "$out/twin.qcells" ] || "$binary" certify --set "fractal.c=[-0.122561,0.744862,0,0]" \
    --resolution 512 -o "$out/twin.qcells" > /dev/null
  certified "trueset-render-rabbit-twin-360p" --set "fractal.c=[-0.122561,0.744862,0,0]" \
    --set "render.certified=\"$out/twin.qcells\""
  certified "trueset-render-rabbit-twin-KN-360p" --set "fractal.c=[-0.122561,0.744862,0,0]"
fi
[ -n "${rows:-}" ] && return 0
# Films (`quaternia animate`): the hidden-turn preset at 1 sample on 2 threads, frames per second
# end to end (every PNG written, the process start left out) and of the render loop alone (the
# sum of the frames' render seconds); the ratio is how much of the render speed the film keeps
# (the writer thread encodes and writes frame n while frame n + 1 renders).
film() {  # name, frames, then quaternia animate arguments
  local name=$1 frames=$2; shift 2
  : > "$out/films.jsonl"
  for _ in $(seq "$runs"); do
    "$binary" animate --preset hidden-turn --frames "1-$frames" --overwrite --threads 2 \
      --set render.samples=1 "$@" --json -o "$out/film" >> "$out/films.jsonl"
  done
  python3 -c '
import json, statistics, sys
runs = [json.loads(line) for line in sys.stdin]
end_to_end = statistics.median(r["frames_rendered"] / r["seconds"] for r in runs)
loop = statistics.median(r["frames_rendered"] / r["render_seconds"] for r in runs)
r = runs[0]
print("%-24s %-10s %6.1f frames/s end to end %6.1f frames/s render loop  ratio %3.0f%%  (%d frames, median of %d, %d threads)"
      % (sys.argv[1], "%dx%d" % (r["width"], r["height"]), end_to_end, loop, 100 * end_to_end / loop,
         r["frames_rendered"], len(runs), r["threads"]))
' "$name" < "$out/films.jsonl"
}
echo
echo "film                     size"
film hidden-turn-360p 60 --width 640 --height 360
film hidden-turn-1080p 12 --width 1920 --height 1080

# Meshes of the default scene: median time and peak memory (GNU time's maximum resident set).
mesh() {  # resolution
  : > "$out/meshes.txt"
  for _ in $(seq "$runs"); do
    /usr/bin/time -f '%M' -o "$out/rss" "$binary" mesh --resolution "$1" --json -o "$out/mesh.stl" \
      > "$out/mesh.json"
    python3 -c 'import json, sys; r = json.load(sys.stdin); print(r["seconds"], r["triangles"], r["threads"], open(sys.argv[1]).read().strip())' "$out/rss" \
      < "$out/mesh.json" >> "$out/meshes.txt"
  done
  python3 -c '
import statistics, sys
runs = [line.split() for line in sys.stdin]
seconds = statistics.median(float(r[0]) for r in runs)
rss = max(int(r[3]) for r in runs) / 1024
print("%-24s %9.2f s %10d triangles %8.0f MB peak  (median of %d, %s threads)"
      % ("mesh-default-" + sys.argv[1], seconds, int(runs[0][1]), rss, len(runs), runs[0][2]))
' "$1" < "$out/meshes.txt"
}
echo
echo "mesh                     time      size                 memory"
mesh 256
mesh 512

if [ -x build/quaternia_bench ]; then
  build/quaternia_bench --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
fi
}
tables | tee -a "$report"
echo '```' >> "$report"
echo "bench/run.sh: wrote $report" >&2
