#!/usr/bin/env bash
# Rays per second of path-traced renders against the diffuse single-ray rate `raylab bench`
# measures on the same scene (issue 30's bar: at least 0.6x): the Cornell box, and the bunny
# and igea under a constant environment light, at 1 and 2 threads. Medians of 3 runs each; the
# rays of a render are every ray it traced (camera, bounce and shadow rays), from its summary.
#   usage: scripts/path-throughput.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
raylab="$build/bin/raylab"
scenes=${SCENES:-"cornell ../shared/scenes/stanford-bunny.obj ../shared/scenes/igea.ply"}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
median() { sort -g | awk '{a[NR] = $1} END {print a[int((NR + 1) / 2)]}'; }
echo "| scene | threads | diffuse Mrays/s (bench) | path Mrays/s (render) | path / diffuse |"
echo "|---|---|---|---|---|"
for scene in $scenes; do
  env=()
  [ "$scene" = cornell ] || env=(--env 1,1,1 --allow-outside-paths)
  for threads in 1 2; do
    diffuse=$("$raylab" bench "$scene" --rays diffuse --against none --threads "$threads" --repeats 3 --width 512 \
      --height 512 ${env[1]:+--allow-outside-paths} 2>/dev/null | awk '/^diffuse single Mrays/ {print $5}')
    path=$(for rep in 1 2 3; do
      "$raylab" render "$scene" --integrator path "${env[@]}" --width 256 --height 256 --spp 16 --threads "$threads" \
        -o "$out/p.png" 2>&1 | sed -n 's/.* rays at \([0-9.]*\) Mrays\/s.*/\1/p'
    done | median)
    ratio=$(echo "scale=2; $path / $diffuse" | bc)
    echo "| $(basename "$scene") | $threads | $diffuse | $path | $ratio |"
  done
done
