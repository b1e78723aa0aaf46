#!/usr/bin/env bash
# raylab's path integrator against Blender's Cycles (CPU, denoiser off) on the Cornell box, at
# equal maximum depth and equal samples per pixel: samples per second, and the time each needs
# to reach the same error against its own high-sample reference (plus how far the two
# references are apart, which says whether they render the same thing). Cycles is a yardstick,
# not a dependency: without `blender` on PATH the script says so and exits 0.
#   usage: scripts/cycles-compare.sh [BUILD_DIR] [THREADS] [SIZE] [MAX_DEPTH]
# Figures and the command line go to docs/performance.md by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
threads=${2:-2}
size=${3:-128}
depth=${4:-6}
if ! command -v blender >/dev/null 2>&1; then
  echo "cycles-compare: skipped: blender is not installed (apt-get install blender to compare with Cycles)"
  exit 0
fi
raylab="$build/bin/raylab"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$raylab" convert cornell "$work/cornell.obj" --quiet

run_cycles() {  # SPP SEED OUT -> seconds
  blender -b --factory-startup -P scripts/cycles_cornell.py -- "$work/cornell.obj" "$3" "$1" "$depth" "$threads" "$2" \
    "$size" 2>/dev/null | awk '/^cycles-seconds/ {print $2}'
}
run_raylab() {  # SPP SEED OUT -> seconds
  local start end
  start=$(date +%s.%N)
  "$raylab" render cornell --integrator path --width "$size" --height "$size" --spp "$1" --sampler sobol \
    --max-depth "$depth" --seed "$2" --threads "$threads" --quiet -o "$3"
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

ref_spp=${REF_SPP:-4096}
echo "references at $ref_spp spp ..." >&2
run_cycles "$ref_spp" 101 "$work/cycles-ref.exr" >/dev/null
run_raylab "$ref_spp" 101 "$work/raylab-ref.exr" >/dev/null

{
  for spp in 4 16 64 256; do
    for rep in 1 2 3; do
      c=$(run_cycles "$spp" "$rep" "$work/cycles-$spp-$rep.exr")
      r=$(run_raylab "$spp" "$rep" "$work/raylab-$spp-$rep.exr")
      echo "$spp $rep $c $r"
    done
  done
} > "$work/times.txt"
PYTHONPATH="$build/python" /usr/bin/python3 scripts/cycles-compare.py "$work" "$size" "$depth" "$threads"
