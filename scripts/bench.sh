#!/usr/bin/env bash
# Measures what docs/performance.md reports. Usage: scripts/bench.sh [BUILD_DIR]
# Render times of the demo at 1280x720 (1 and 16 spp, 1 and 2 threads), then `raylab bench` (our
# BVH against Embree 3 on the same rays) on the scenes of issue 6. Figures go to stdout.
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
    # The one summary line on stderr ("wrote ... rays at R Mrays/s, ...) in Ts") carries both.
    line=$("$raylab" render demo --width 1280 --height 720 --spp "$spp" --threads "$threads" -o "$out/demo.pfm" 2>&1 >/dev/null | tail -n 1)
    secs=$(sed -E 's/.* in ([0-9.]+)s$/\1/; s/.* in ([0-9]+m[0-9]+s)$/\1/' <<<"$line")
    mrays=$(sed -E 's/.* ([0-9.]+) Mrays\/s.*/\1/' <<<"$line")
    echo "| $spp | $threads | $secs | $mrays |"
  done
done

# Our BVH against Embree 3 on the same rays (`raylab bench`, docs/command-line.md) on the scenes of
# issue 6, with 1 and 2 threads: the bunny on a ground quad, igea, spd:balls (analytic spheres as
# Embree user geometry) and spd:mount at level 10 (2.1M triangles). Each table is preceded by the
# command that produced it; a scene whose file is missing is skipped with a note.
shared=../shared/scenes
for scene in bench/scenes/bunny-on-ground-triangles.json bench/scenes/bunny-on-ground.json "$shared/igea.ply" spd:balls 'spd:mount?size=10'; do
  case "$scene" in
    spd:*) ;;
    *) if [ ! -f "$scene" ]; then echo; echo "(skipped $scene: not found)"; continue; fi ;;
  esac
  repeats=5
  case "$scene" in spd:mount*) repeats=3 ;; esac  # 2.1M triangles: each repeat rebuilds both
  # Embree's own choice of kernels (AVX-512 on this CPU) with 1 and 2 threads, then Embree held
  # to AVX2 like the release build, one thread.
  for variant in "1 best" "2 best" "1 avx2"; do
    read -r threads isa <<<"$variant"
    cmd=("$raylab" bench "$scene" --allow-outside-paths --threads "$threads" --repeats "$repeats" --embree-isa "$isa" -q)
    echo
    echo "## \`raylab bench $scene --allow-outside-paths --threads $threads --repeats $repeats --embree-isa $isa\`"
    echo '```'
    "${cmd[@]}"
    echo '```'
  done
done
