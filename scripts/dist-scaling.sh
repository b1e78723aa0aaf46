#!/usr/bin/env bash
# The scaling table of docs/distributed.md: one fixed render on N = 1, 2, 4 MPI ranks of one
# thread each (on a 2-core machine, 4 ranks oversubscribe the cores), REPEATS runs each, the
# median wall time, the speedup and the parallel efficiency, and (from one more run with --stats)
# each rank's tiles and busy time and the load imbalance.
# Usage: scripts/dist-scaling.sh BUILD_DIR [REPEATS] [SCENE ARGS...]
set -euo pipefail
build_dir=${1:?usage: dist-scaling.sh BUILD_DIR [REPEATS] [SCENE ARGS...]}
repeats=${2:-3}
shift $(($# >= 2 ? 2 : 1))
scene=("$@")
[ ${#scene[@]} -gt 0 ] || scene=(demo --width 640 --height 400 --spp 16)
raylab="$build_dir/bin/raylab"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }

echo "render: raylab render ${scene[*]} --threads 1 (per rank); $repeats runs each; $(nproc) cores"
echo "| ranks | median wall s | speedup | efficiency | tiles per rank (--stats run) | busy s per rank (--stats run) | imbalance |"
echo "|---|---|---|---|---|---|---|"
t1=""
for n in 1 2 4; do
  times=()
  # The per-rank columns come from one run with --stats (its counting kernels are slower); the
  # times from runs without it.
  mpirun --oversubscribe --allow-run-as-root -np "$n" "$raylab" render "${scene[@]}" --threads 1 -q --stats \
    -o "$work/out.png" >"$work/stats.txt"
  for ((i = 0; i < repeats; i++)); do
    start=$(date +%s.%N)
    mpirun --oversubscribe --allow-run-as-root -np "$n" "$raylab" render "${scene[@]}" --threads 1 -q \
      -o "$work/out.png"
    end=$(date +%s.%N)
    times+=("$(awk -v a="$start" -v b="$end" 'BEGIN {print b - a}')")
  done
  t=$(printf '%s\n' "${times[@]}" | median)
  [ -n "$t1" ] || t1=$t
  speedup=$(awk -v a="$t1" -v b="$t" 'BEGIN {print a / b}')
  efficiency=$(awk -v s="$speedup" -v n="$n" 'BEGIN {print s / n}')
  tiles=$(awk '/^[0-9]+ +[^ ]+ +[0-9]+ +[0-9]+ +[0-9]+/ {printf "%s%s", sep, $4; sep="/"}' "$work/stats.txt")
  busy=$(awk '/^[0-9]+ +[^ ]+ +[0-9]+ +[0-9]+ +[0-9]+/ {printf "%s%s", sep, $6; sep="/"}' "$work/stats.txt")
  imbalance=$(awk '/^load imbalance/ {print $3}' "$work/stats.txt")
  printf '| %d | %.2f | %.2f | %.2f | %s | %s | %s |\n' "$n" "$t" "$speedup" "$efficiency" "$tiles" "$busy" "$imbalance"
done
