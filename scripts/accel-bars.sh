#!/usr/bin/env bash
# The speed bars of the space-subdivision structures (issue 22, docs/accelerators.md): `raylab
# compare` with one thread on the seven SPD scenes, the four shared meshes and the two benchmark
# scenes, every structure against the BVH in the same run, then the ratio tables
# (scripts/accel-ratios.py) with the ratios under each bar marked.
#
# usage: scripts/accel-bars.sh [BUILD_DIR] [JSON_DIR] [ACCELS]
#   defaults: build/release, a temporary folder, bvh,grid,grid2,irregular,octree
# Takes about ten minutes on the 2-core development machine.
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
out=${2:-}
accels=${3:-bvh,grid,grid2,irregular,octree}
raylab="$build/bin/raylab"
[ -x "$raylab" ] || { echo "no $raylab: build first" >&2; exit 2; }
if [ -z "$out" ]; then
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
mkdir -p "$out"
status=0
run() {  # scene [extra options]
  local scene=$1
  shift
  local name
  name=$(basename "$scene" | tr ':?=' '___')
  echo "\$ raylab compare $scene --accels $accels --threads 1 $*" >&2
  "$raylab" compare "$scene" --accels "$accels" --threads 1 -q "$@" --json "$out/$name.json" >/dev/null || status=1
}
for g in balls gears mount rings teapot tetra tree; do run "spd:$g"; done
for m in stanford-bunny.obj armadillo.off igea.ply nefertiti.obj; do run "../shared/scenes/$m"; done
run bench/scenes/bunny-on-ground.json --allow-outside-paths
run bench/scenes/teapot-in-stadium.json
/usr/bin/python3 scripts/accel-ratios.py "$out"/spd_*.json "$out"/*.obj.json "$out"/*.off.json "$out"/*.ply.json \
  "$out"/bunny-on-ground.json.json "$out"/teapot-in-stadium.json.json \
  --bars irregular=0.8,0.6,0.6 grid2=0.5,0,0 octree=0.5,0,0
exit $status
