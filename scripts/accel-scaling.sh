#!/usr/bin/env bash
# How every structure scales with the number of primitives: `raylab compare` on spd:balls (sizes 1
# to 7: 10 to 5.4 million spheres) and spd:mount (sizes 3 to 11: 128 to 8.4 million triangles),
# one JSON per run, then log-log SVG plots of primary-ray Mrays/s and build time against the
# primitive count, and a Markdown table on stdout (docs/accelerators.md shows both).
#
# usage: scripts/accel-scaling.sh [BUILD_DIR] [OUT_DIR]   (defaults: build/release docs/images)
# Takes about half an hour on 2 cores; brute force is skipped where it would take over a minute.
# The environment can narrow the run: ACCELS (default: every structure, Embree when built in),
# BALLS_SIZES (default "1 2 3 4 5 6 7"), MOUNT_SIZES ("3 4 5 6 7 8 9 10 11"), SIZE (pixels per
# side, 256), THREADS (default: all cores).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-docs/images}
raylab="$build/bin/raylab"
[ -x "$raylab" ] || { echo "no $raylab: build first (cmake --preset release && cmake --build build/release)" >&2; exit 2; }
accels=${ACCELS:-brute,grid,grid2,irregular,octree,bvh}
[ -z "${ACCELS:-}" ] && "$raylab" compare --help | grep -q embree && accels="$accels,embree"
size=${SIZE:-256}
threads=()
[ -n "${THREADS:-}" ] && threads=(--threads "$THREADS")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {  # generator size
  echo "spd:$1?size=$2" >&2
  "$raylab" compare "spd:$1?size=$2" --accels "$accels" --width "$size" --height "$size" --repeat 3 -q "${threads[@]}" \
    --json "$work/$1-$2.json" >/dev/null || echo "  (exit $?: see the table)" >&2
}
for s in ${BALLS_SIZES:-1 2 3 4 5 6 7}; do run balls "$s"; done
for s in ${MOUNT_SIZES:-3 4 5 6 7 8 9 10 11}; do run mount "$s"; done
mkdir -p "$out"
/usr/bin/python3 scripts/plot-scaling.py --out "$out" "$work"/*.json
