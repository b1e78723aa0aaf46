#!/usr/bin/env bash
# End-to-end speed of raylab against an earlier commit on the seven SPD scenes (issue 31).
#
# Builds BASE (default 42ab994, the commit issue 31 measures against) in a git worktree beside
# this checkout and this checkout's release build, then renders each NFF file of
# ../shared/spd-reference by the SPD testing procedure (512x512, rays through the pixel corners,
# depth 5) with both, RUNS times each (default 5), alternating which goes first, and times the
# whole process. Prints, per scene, the median seconds of each side, base / current, whether the
# images are identical byte for byte (PFM: raw floats) and whether the SPD ray counts agree.
#
# usage: scripts/spd-end-to-end.sh [--base COMMIT] [--runs N] [--threads N] [--work DIR]
#   --work DIR   where the worktree, its build and the renders go (default build/e2e)
# Needs what `make test` installs; builds only the command-line program on each side.
set -euo pipefail

root=$(git -C "$(dirname "$0")" rev-parse --show-toplevel)
base=42ab994
runs=5
threads=2
work="$root/build/e2e"
while [ $# -gt 0 ]; do
  case "$1" in
    --base) base=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    -h|--help) sed -n '2,14p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "spd-end-to-end: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done
case "$runs$threads" in *[!0-9]*) echo "spd-end-to-end: --runs and --threads take whole numbers" >&2; exit 2 ;; esac
scenes_dir="$root/../shared/spd-reference"
[ -d "$scenes_dir" ] || { echo "spd-end-to-end: $scenes_dir not found" >&2; exit 1; }
python=/usr/bin/python3

# The base commit in its own worktree (reused when it is already there at that commit).
base_sha=$(git -C "$root" rev-parse --verify "$base^{commit}")
base_src="$work/base-src"
mkdir -p "$work"
if [ -d "$base_src" ] && [ "$(git -C "$base_src" rev-parse HEAD)" != "$base_sha" ]; then
  git -C "$root" worktree remove --force "$base_src"
fi
[ -d "$base_src" ] || git -C "$root" worktree add --detach "$base_src" "$base_sha" >/dev/null

build() {  # build SOURCE_DIR: the release preset's command-line program
  (cd "$1" && cmake --preset release >/dev/null && cmake --build build/release --target raylab_cli >/dev/null)
}
echo "building $base (${base_sha:0:12}) in $base_src" >&2
build "$base_src"
echo "building the current checkout ($(git -C "$root" rev-parse --short HEAD))" >&2
build "$root"
declare -A bin=([base]="$base_src/build/release/bin/raylab" [current]="$root/build/release/bin/raylab")

out="$work/renders"
rm -rf "$out" && mkdir -p "$out"
times="$work/times.txt"
: >"$times"
render() {  # render SIDE SCENE RUN: one timed whole-process render
  local side=$1 scene=$2 run=$3 start end
  start=$(date +%s%N)
  "${bin[$side]}" render "$scenes_dir/$scene.nff" --spd-protocol --threads "$threads" -q --allow-outside-paths \
    -o "$out/$scene.$side.pfm" --json "$out/$scene.$side.json" >/dev/null
  end=$(date +%s%N)
  echo "$scene $side $run $(( (end - start) / 1000 ))" >>"$times"
}
scenes=(balls gears mount rings teapot tetra tree)
for run in $(seq 1 "$runs"); do
  for scene in "${scenes[@]}"; do
    echo "run $run/$runs: $scene" >&2
    # Alternate which side goes first, so that neither always meets a warm or a cold cache.
    if [ $((run % 2)) -eq 1 ]; then order=(base current); else order=(current base); fi
    for side in "${order[@]}"; do render "$side" "$scene" "$run"; done
  done
done

# The processor, as the figures need it said: name, family and model, and whether AVX-512 is there.
lscpu_model="$(lscpu | sed -n 's/^Model name: *//p' | head -1) (family $(lscpu | sed -n 's/^CPU family: *//p' | head -1), \
model $(lscpu | sed -n 's/^Model: *//p' | head -1), $(grep -q avx512f /proc/cpuinfo && echo AVX-512 || echo 'no AVX-512'))"

"$python" - "$times" "$out" "$base" "$threads" "$runs" "$lscpu_model" "${scenes[@]}" <<'EOF'
import filecmp, json, statistics, sys
times_file, out, base, threads, runs, cpu, *scenes = sys.argv[1:]
seconds = {}
for line in open(times_file):
    scene, side, _, micros = line.split()
    seconds.setdefault((scene, side), []).append(int(micros) / 1e6)

def counts(scene, side):
    with open(f"{out}/{scene}.{side}.json") as f:
        j = json.load(f)
    return j["rays"], j["total_internal_reflections"]

print(f"SPD scenes end to end, {threads} threads, median of {runs} alternating runs, whole process; {cpu}")
print(f"| scene | {base} s | current s | {base} / current | image | SPD counts |")
print("|---|---|---|---|---|---|")
for scene in scenes:
    b = statistics.median(seconds[(scene, "base")])
    c = statistics.median(seconds[(scene, "current")])
    same_image = filecmp.cmp(f"{out}/{scene}.base.pfm", f"{out}/{scene}.current.pfm", shallow=False)
    same_counts = counts(scene, "base") == counts(scene, "current")
    print(f"| {scene} | {b:.3f} | {c:.3f} | **{b / c:.2f}x** | {'identical' if same_image else 'DIFFERS'} "
          f"| {'identical' if same_counts else 'DIFFER'} |")
EOF
