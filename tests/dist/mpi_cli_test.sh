#!/usr/bin/env bash
# End-to-end tests of `mpirun -np N raylab render` (ctest runs one case per test; see
# tests/CMakeLists.txt). Usage: mpi_cli_test.sh CASE RAYLAB SOURCE_DIR MPIEXEC [PREFLAGS...]
#   identical  the image of N = 1, 2, 3 ranks has the bytes of the single-process render
#              (box filter; gaussian in 2 passes)
#   killed     a worker killed mid-render (1 s after the first checkpoint): the run fails naming the rank and its tiles, writes
#              no image, leaves a checkpoint that resumes (under MPI) to the same bytes
#   disagree   a rank with other settings: refused by name before any tile, no image
#   frames     --frames under 3 ranks: every frame has the bytes of the single-process frames
#   stats      --stats prints one row per rank and the load imbalance
set -uo pipefail
case_name=$1 raylab=$2 source_dir=$3 mpiexec=$4
shift 4
preflags=("$@")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mpi() { local n=$1; shift; "$mpiexec" -n "$n" "${preflags[@]}" "$@"; }
small=(demo --width 96 --height 64 --spp 4 -q)

case $case_name in
identical)
  "$raylab" render "${small[@]}" -o local.png || fail "local render"
  "$raylab" render "${small[@]}" --filter gaussian --passes 2 -o local-g.png || fail "local gaussian render"
  for n in 1 2 3; do
    mpi "$n" "$raylab" render "${small[@]}" -o "mpi$n.png" || fail "mpi render with $n ranks"
    cmp -s local.png "mpi$n.png" || fail "$n ranks: image differs from the local render"
    mpi "$n" "$raylab" render "${small[@]}" --filter gaussian --passes 2 -o "mpi-g$n.png" || fail "gaussian, $n ranks"
    cmp -s local-g.png "mpi-g$n.png" || fail "$n ranks, gaussian in 2 passes: image differs"
  done
  # The path integrator draws every random number from (pixel, sample, dimension) too.
  path=(cornell --integrator path --width 40 --height 30 --spp 8 -q)
  "$raylab" render "${path[@]}" -o local-path.pfm || fail "local path render"
  for n in 1 3; do
    mpi "$n" "$raylab" render "${path[@]}" -o "mpi-path$n.pfm" || fail "path, $n ranks"
    cmp -s local-path.pfm "mpi-path$n.pfm" || fail "$n ranks, path integrator: image differs"
  done
  ;;
killed)
  long=(demo --width 320 --height 200 --spp 64 -q)
  "$raylab" render "${long[@]}" -o reference.png || fail "reference render"
  # Rank 1 is killed (SIGKILL) 1 s after rank 0's first checkpoint (every 0.5 s), i.e. well into
  # the render, however long the ranks took to start; the render takes several seconds more.
  cat >die.sh <<'SCRIPT'
#!/bin/sh
if [ "${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}" = "1" ]; then
  (i=0; while [ ! -e out.ckpt ] && [ $i -lt 600 ]; do sleep 0.1; i=$((i + 1)); done; sleep 1; kill -9 $$) &
fi
exec "$@"
SCRIPT
  chmod +x die.sh
  mpi 3 ./die.sh "$raylab" render "${long[@]}" --threads 1 -o out.png --checkpoint out.ckpt --checkpoint-every 0.5 \
    2>err.txt
  status=$?
  cat err.txt
  [ "$status" -ne 0 ] || fail "the run with a dead rank exited 0"
  grep -q "rank 1 held tile" err.txt || fail "the message does not name rank 1 and its tiles"
  [ ! -e out.png ] || fail "an image was written by a run with a dead rank"
  [ -s out.ckpt ] || fail "no checkpoint left to resume from"
  ls -A | grep -q '\.tmp' && fail "a temporary file was left behind"
  mpi 2 "$raylab" render -o out.png --resume out.ckpt -q || fail "resuming under MPI"
  cmp -s reference.png out.png || fail "the resumed image differs from the uninterrupted render"
  ;;
disagree)
  cat >seed.sh <<'SCRIPT'
#!/bin/sh
if [ "${OMPI_COMM_WORLD_RANK:-${PMI_RANK:-0}}" = "2" ]; then exec "$@" --seed 7; fi
exec "$@"
SCRIPT
  chmod +x seed.sh
  mpi 3 ./seed.sh "$raylab" render "${small[@]}" -o out.png 2>err.txt
  status=$?
  cat err.txt
  [ "$status" -ne 0 ] || fail "ranks with other settings: exit 0"
  grep -q "rank 2 .*another scene or other settings" err.txt || fail "the message does not name rank 2"
  [ ! -e out.png ] || fail "an image was written"
  ;;
frames)
  scene="$source_dir/scenes/orbit.json"
  "$raylab" render "$scene" --frames 3:8 --width 64 --height 48 -q -o "local.####.png" || fail "local frames"
  mpi 3 "$raylab" render "$scene" --frames 3:8 --width 64 --height 48 -q -o "mpi.####.png" || fail "mpi frames"
  for f in 0003 0004 0005 0006 0007 0008; do
    cmp -s "local.$f.png" "mpi.$f.png" || fail "frame $f differs between 3 ranks and one process"
  done
  [ ! -e local.0002.png ] && [ ! -e local.0009.png ] || fail "frames outside 3:8 were written"
  ;;
stats)
  mpi 3 "$raylab" render "${small[@]}" -o out.png --stats >out.txt || fail "render with --stats"
  cat out.txt
  rows=$(grep -cE '^[0-2] +[^ ]+ +[0-9]+ +[0-9]+ +[0-9]+' out.txt)
  [ "$rows" -eq 3 ] || fail "expected 3 rank rows in --stats, found $rows"
  grep -q "^load imbalance" out.txt || fail "no load imbalance line"
  ;;
*)
  echo "unknown case $case_name"
  exit 2
  ;;
esac
[ "$failures" -eq 0 ] && echo "mpi $case_name: ok"
exit $((failures > 0))
