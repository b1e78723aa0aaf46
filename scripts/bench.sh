#!/usr/bin/env bash
# Measures what docs/performance.md reports. Usage: scripts/bench.sh [BUILD_DIR]
# Render times of the demo at 1280x720 (1 and 16 spp, 1 and 2 threads), then the BVH against
# Embree on the Stanford bunny (if the benchmark was built). Figures go to stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
raylab="$build/bin/raylab"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "## demo at 1280x720"
echo "| spp | threads | render seconds | Mrays/s |"
echo "|---|---|---|---|"
for spp in 1 16; do
  for threads in 1 2; do
    # The summary line on stderr (not a terminal here) carries the time and the ray rate.
    line=$("$raylab" render demo --width 1280 --height 720 --spp "$spp" --threads "$threads" -o "$out/demo.pfm" 2>&1 >/dev/null | tail -n 1)
    secs=$(sed -E 's/.* in ([0-9.]+)s$/\1/; s/.* in ([0-9]+m[0-9]+s)$/\1/' <<<"$line")
    mrays=$(sed -E 's/.*\(([0-9.]+) Mrays\/s\).*/\1/' <<<"$line")
    echo "| $spp | $threads | $secs | $mrays |"
  done
done

bunny=../shared/scenes/stanford-bunny.obj
if [ -x "$build/bin/bvh_vs_embree" ] && [ -f "$bunny" ]; then
  echo
  echo "## BVH and Embree on $bunny"
  "$build/bin/bvh_vs_embree" "$bunny"
fi
