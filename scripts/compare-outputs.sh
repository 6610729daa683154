#!/usr/bin/env bash
# Proves that a change which is not meant to change pictures does not: runs the same commands
# with two builds of quaternia, under each instruction set named, and compares every output
# byte for byte (PNG, 16-bit PNG, depth, EXR, animation frames, plane images, meshes, orbit and
# cycle JSON).
#   scripts/compare-outputs.sh BEFORE/quaternia AFTER/quaternia [ISA...]   (default: avx2 best)
# Prints one line per output, "same" or "DIFFERS", and a count; exits 1 if any differs.
set -uo pipefail
before=${1:?usage: scripts/compare-outputs.sh BEFORE AFTER [ISA...]}
after=${2:?usage: scripts/compare-outputs.sh BEFORE AFTER [ISA...]}
shift 2
before=$(realpath "$before") after=$(realpath "$after")  # the runs change directory
isas=("${@:-avx2 best}")
[ $# -eq 0 ] && isas=(avx2 best)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

small=(--width 160 --height 90)
map=$(realpath "$(dirname "$0")/../data/environments/studio.hdr")  # the shipped environment map
# name|command|output file (relative to the run's folder; "-" for standard output)
jobs=(
  "default|render ${small[*]} -o out.png|out.png"
  "default-4spp-16bit|render ${small[*]} --set render.bit_depth=16 -o out.png|out.png"
  "default-depth|render ${small[*]} --depth depth.png -o out.png|depth.png"
  "default-exr|render ${small[*]} -o out.exr|out.exr"
  "adaptive|render ${small[*]} --set render.adaptive=true --set render.samples=16 -o out.png|out.png"
  "scalar|render ${small[*]} --set render.engine=scalar -o out.png|out.png"
  "double|render ${small[*]} --set render.precision=double -o out.png|out.png"
  "studio|render ${small[*]} --preset studio -o out.png|out.png"
  "chrome|render ${small[*]} --preset chrome -o out.png|out.png"
  "glass|render ${small[*]} --preset glass -o out.png|out.png"
  "sunset|render ${small[*]} --preset sunset -o out.png|out.png"
  "environment-map|render ${small[*]} --set environment.enabled=true --set environment.map='\"$map\"' --set material.reflectivity=0.4 --set material.roughness=0.1 --set ground.enabled=true -o out.png|out.png"
  "rabbit|render ${small[*]} --preset rabbit -o out.png|out.png"
  "cubic|render ${small[*]} --preset cubic -o out.png|out.png"
  "two-sided|render ${small[*]} --preset two-sided -o out.png|out.png"
  "program|render ${small[*]} --set fractal.formula=z^2+0.1*z+c -o out.png|out.png"
  "glow-fog|render ${small[*]} --set shading.glow_intensity=1 --set shading.fog_density=0.2 -o out.png|out.png"
  "bicomplex-connected|render ${small[*]} --set fractal.algebra=bicomplex --set fractal.c=[-0.3,0.2,0.1,0.1] -o out.png|out.png"
  "bicomplex-default|render ${small[*]} --set fractal.algebra=bicomplex -o out.png|out.png"
  "octonion|render ${small[*]} --set fractal.algebra=octonion --set fractal.c=[-0.2,0.6,0.2,0.2,0.1,0,0.05,0] -o out.png|out.png"
  "coquaternion|render --width 48 --height 27 --set fractal.algebra=coquaternion -o out.png|out.png"
  "animate|animate --width 64 --height 36 --frames 2 -o frames --set animation.frames=3 --set animation.c_radius=0.1|frames/frame_000002.png"
  "plane-julia|plane --width 96 --height 64 -o out.png|out.png"
  "plane-boundary|plane --width 96 --height 64 --set plane.kind=julia-boundary -o out.png|out.png"
  "plane-mandelbrot|plane --width 96 --height 64 --set plane.kind=mandelbrot -o out.png|out.png"
  "plane-basins|plane --width 96 --height 64 --preset rabbit --set plane.kind=basins -o out.png|out.png"
  "plane-slice|plane --width 96 --height 64 --set plane.kind=slice -o out.png|out.png"
  "mesh-stl|mesh --resolution 48 -o out.stl|out.stl"
  "mesh-ply|mesh --resolution 40 --preset rabbit -o out.ply|out.ply"
  "mesh-obj|mesh --resolution 32 --set fractal.formula=z^3+c -o out.obj|out.obj"
  "orbit-default|orbit --json|-"
  "orbit-rabbit|orbit --preset rabbit --z0 0.1+0.05i --json|-"
  "orbit-coquaternion|orbit --set fractal.algebra=coquaternion --json|-"
  "cycles|cycles --c -1 --period 2 --json|-"
)

differ=0 total=0
for isa in "${isas[@]}"; do
  for entry in "${jobs[@]}"; do
    IFS='|' read -r name command file <<<"$entry"
    for side in before after; do
      binary=$before
      [ $side = after ] && binary=$after
      mkdir -p "$work/$side/$isa/$name"
      (cd "$work/$side/$isa/$name" &&
        eval "\"$binary\" --isa $isa $command" >stdout 2>stderr) || true
    done
    pick() { [ "$file" = - ] && echo "$work/$1/$isa/$name/stdout" || echo "$work/$1/$isa/$name/$file"; }
    total=$((total + 1))
    if [ -s "$(pick before)" ] && cmp -s "$(pick before)" "$(pick after)"; then
      echo "same     $isa $name"
    else
      echo "DIFFERS  $isa $name"
      differ=$((differ + 1))
    fi
  done
done
echo "$((total - differ)) of $total outputs byte-identical"
[ $differ -eq 0 ]
