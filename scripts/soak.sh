#!/usr/bin/env bash
# Soak test of long renders (not part of the default CI run; docs/reliability.md reports its
# runs). Each of RENDERS renders (three scenes, two samplers, box and gaussian filters, one or three
# passes) is interrupted at random moments, by SIGINT, SIGTERM, two SIGINTs or SIGKILL, and
# resumed from its checkpoint until it completes; after every interruption the image must be absent
# or whole and no temporary may be left (SIGKILL excepted: nothing can clean up after it); at the
# end the image must equal, byte for byte, the same render done in one go, and the checkpoint must
# be gone. Prints the counts; exits 1 when anything went wrong.
#
# Usage: scripts/soak.sh [BUILD_DIR] [RENDERS] [SEED]      (defaults: build/release 50 1)
set -uo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
renders=${2:-50}
RANDOM=${3:-1}
raylab="$build/bin/raylab"
[ -x "$raylab" ] || { echo "soak: no $raylab (build first: make test)"; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

configs=(
  "demo --width 320 --height 180 --spp 16"
  "cornell --width 192 --height 192 --spp 9 --filter gaussian"
  "spd:balls?size=2 --width 240 --height 160 --spp 4 --sampler sobol"
)
signals=(INT TERM KILL INTINT)
declare -A interrupted=([INT]=0 [TERM]=0 [KILL]=0 [INTINT]=0)
resumes=0 identical=0 mismatches=0 whole_checks=0 damaged=0 strays_after_kill=0 strays=0 failures=0 leftover=0
finished_before_signal=0

# Whether PFM file $1 is whole: its header's size times 12 bytes of pixels, nothing more or less.
pfm_whole() {
  local header w h
  header=$(head -c 64 "$1" | head -n 2 | tail -n 1)
  read -r w h <<<"$header"
  local header_bytes
  header_bytes=$(head -n 3 "$1" | wc -c)
  [ "$(stat -c %s "$1")" -eq $((header_bytes + w * h * 12)) ]
}

# The references: each configuration rendered in one go, in one and in three passes (with a filter
# wider than a pixel, passes add a pixel's neighbours' samples in another order).
for ((i = 0; i < ${#configs[@]}; i++)); do
  for passes in 1 3; do
    # shellcheck disable=SC2086  # the configuration is a list of words
    "$raylab" render ${configs[$i]} --passes $passes -q -o "$work/reference$i-$passes.pfm" ||
      { echo "soak: reference $i failed"; exit 1; }
  done
done

for ((r = 1; r <= renders; r++)); do
  c=$((RANDOM % ${#configs[@]}))
  passes=$((RANDOM % 2 ? 1 : 3))
  image="$work/render.pfm" checkpoint="$work/render.ckpt"
  rm -f "$image" "$checkpoint"
  for ((attempt = 0; ; attempt++)); do
    args=(render ${configs[$c]} --passes "$passes" --threads 2 -q -o "$image" --checkpoint "$checkpoint"
      --checkpoint-every 0.05)
    if [ -f "$checkpoint" ]; then
      args+=(--resume "$checkpoint")
      resumes=$((resumes + 1))
    fi
    "$raylab" "${args[@]}" 2>"$work/err.txt" &
    pid=$!
    if [ "$attempt" -ge 12 ]; then  # enough: let it finish
      { wait "$pid"; } 2>/dev/null
      code=$?
      [ "$code" -eq 0 ] || { echo "soak: render $r: exit $code: $(cat "$work/err.txt")"; failures=$((failures + 1)); }
      break
    fi
    sig=${signals[$((RANDOM % 4))]}
    sleep "0.$(printf %03d $((RANDOM % 400)))"
    if [ "$sig" = INTINT ]; then
      kill -s INT "$pid" 2>/dev/null
      kill -s INT "$pid" 2>/dev/null
    else
      kill -s "$sig" "$pid" 2>/dev/null
    fi
    { wait "$pid"; } 2>/dev/null  # (no "Killed" line from the shell)
    code=$?
    if [ "$code" -eq 0 ]; then
      finished_before_signal=$((finished_before_signal + 1))
      break
    fi
    case "$sig:$code" in
      INT:130 | INTINT:130 | TERM:143 | KILL:137) interrupted[$sig]=$((interrupted[$sig] + 1)) ;;
      *)
        echo "soak: render $r: signal $sig gave exit $code: $(cat "$work/err.txt")"
        failures=$((failures + 1))
        ;;
    esac
    if [ -f "$image" ]; then
      whole_checks=$((whole_checks + 1))
      pfm_whole "$image" || { echo "soak: render $r: half-written image after $sig"; damaged=$((damaged + 1)); }
    fi
    for t in "$work"/*.tmp; do
      [ -e "$t" ] || continue
      if [ "$sig" = KILL ]; then strays_after_kill=$((strays_after_kill + 1)); else
        echo "soak: render $r: temporary $t left after $sig"
        strays=$((strays + 1))
      fi
      rm -f "$t"
    done
  done
  if cmp -s "$image" "$work/reference$c-$passes.pfm"; then identical=$((identical + 1)); else
    echo "soak: render $r (${configs[$c]}, $passes passes) differs from the render done in one go"
    mismatches=$((mismatches + 1))
  fi
  [ -f "$checkpoint" ] && { echo "soak: render $r: checkpoint left after completion"; leftover=$((leftover + 1)); }
done

echo "soak: $renders renders; interrupted by SIGINT ${interrupted[INT]}, SIGTERM ${interrupted[TERM]}," \
  "two SIGINTs ${interrupted[INTINT]}, SIGKILL ${interrupted[KILL]}; finished before the signal $finished_before_signal;" \
  "resumes $resumes"
echo "soak: identical to the render in one go $identical, different $mismatches; images checked whole after" \
  "an interruption $whole_checks, half-written $damaged; temporaries left $strays (after SIGKILL, where" \
  "none can be cleaned, $strays_after_kill); checkpoints left after completion $leftover; other failures $failures"
[ $((mismatches + damaged + strays + leftover + failures)) -eq 0 ]
