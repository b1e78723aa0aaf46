#!/usr/bin/env bash
# Measures scene loading speed for docs/performance.md: a 1,048,576-triangle mesh (spd:tetra at
# size 10) written by `raylab convert` as binary PLY and as OBJ, loaded by `raylab info` (one
# thread: the loaders are sequential). Reports the median load time of REPEATS runs, the file
# size, MB/s of file (1 MB = 10^6 bytes) and the process's peak resident memory.
# Usage: scripts/load-bench.sh [BUILD_DIR] [REPEATS]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
repeats=${2:-5}
raylab="$build/bin/raylab"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

"$raylab" convert 'spd:tetra?size=10' "$out/tetra.ply" -q
"$raylab" convert 'spd:tetra?size=10' "$out/tetra.obj" -q

echo "| format | file MB | triangles | median load s (of $repeats) | MB/s | peak RSS MiB |"
echo "|---|---|---|---|---|---|"
for f in "$out/tetra.ply" "$out/tetra.obj"; do
  bytes=$(stat -c %s "$f")
  times=()
  for ((i = 0; i < repeats; i++)); do
    times+=("$("$raylab" info "$f" | sed -nE 's/^load time +([0-9.]+) s$/\1/p')")
  done
  median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR + 1) / 2)]}')
  triangles=$("$raylab" info "$f" | sed -nE 's/^  triangles ([0-9]+).*/\1/p')
  rss_kib=$(/usr/bin/time -f %M "$raylab" info "$f" 2>&1 >/dev/null | tail -n 1)
  awk -v name="${f##*.}" -v b="$bytes" -v t="$median" -v n="$triangles" -v r="$rss_kib" \
    'BEGIN { printf "| %s | %.1f | %d | %.3f | %.0f | %.0f |\n", name, b / 1e6, n, t, b / 1e6 / t, r / 1024 }'
done
