#!/usr/bin/env bash
# The `raylab compare` table for each of the seven SPD scenes at their default sizes, the meshes
# of ../shared/scenes, and the two benchmark scenes of bench/scenes (docs/accelerators.md).
#
# usage: scripts/accel-tables.sh [BUILD_DIR] [HEATMAP_DIR]   (defaults: build/release, none)
# Prints each command and its table. Exit status: 1 if any comparison found a disagreement.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
heatmaps=${2:-}
raylab="$build/bin/raylab"
[ -x "$raylab" ] || { echo "no $raylab: build first" >&2; exit 2; }
status=0
compare() {  # scene [extra options]
  local scene=$1
  shift
  local extra=()
  if [ -n "$heatmaps" ]; then extra=(--heatmaps "$heatmaps/$(basename "${scene%.*}" | tr ':?=' '___')"); fi
  echo
  echo "\$ raylab compare $scene $*"
  "$raylab" compare "$scene" -q "$@" "${extra[@]}" || status=1
}
for g in balls gears mount rings teapot tetra tree; do compare "spd:$g"; done
for m in ../shared/scenes/*.obj ../shared/scenes/*.ply ../shared/scenes/*.off; do
  [ -f "$m" ] && compare "$m"
done
compare bench/scenes/bunny-on-ground.json --allow-outside-paths
compare bench/scenes/teapot-in-stadium.json
compare spd:balls --grid-density 10 --accels grid,bvh
exit $status
