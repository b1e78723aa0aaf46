#!/usr/bin/env bash
# Runs every libFuzzer target in BUILD_DIR/bin for SECONDS each (make fuzz), as many at once as
# there are cores (FUZZ_JOBS overrides): each target is one process on one core, so running them
# side by side gives every target its full SECONDS and takes a fraction of the time.
# Seeds come from fuzz/corpus/NAME; the growing corpus and any crash input stay under BUILD_DIR.
set -euo pipefail
build_dir=${1:?usage: fuzz.sh BUILD_DIR SECONDS}
seconds=${2:-60}
jobs=${FUZZ_JOBS:-$(nproc)}
root=$(cd "$(dirname "$0")/.." && pwd)
shopt -s nullglob
targets=("$build_dir"/bin/*_fuzz)
if [ ${#targets[@]} -eq 0 ]; then
  echo "fuzz: no targets in $build_dir/bin (configure with the fuzz preset)"
  exit 1
fi

# Fuzzes one target; its exit status is the fuzzer's.
fuzz_one() {
  local target=$1 name work artifacts seeds=()
  name=$(basename "$target" _fuzz)
  work="$build_dir/corpus/$name"
  artifacts="$build_dir/artifacts/$name/"
  mkdir -p "$work" "$artifacts"
  [ -d "$root/fuzz/corpus/$name" ] && seeds=("$root/fuzz/corpus/$name")
  "$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
    -artifact_prefix="$artifacts" -print_final_stats=1 "$work" "${seeds[@]}" >"$build_dir/$name.log" 2>&1
}

declare -A pid_of
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  echo "fuzz: $(basename "$target" _fuzz) for ${seconds}s"
  fuzz_one "$target" &
  pid_of[$target]=$!
done

# Reports in target order, whatever order they finished in.
status=0
for target in "${targets[@]}"; do
  name=$(basename "$target" _fuzz)
  if wait "${pid_of[$target]}"; then
    echo "fuzz: $name: $(grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$build_dir/$name.log" | tr '\n' ' ')"
  else
    echo "fuzz: $name FAILED; input saved in $build_dir/artifacts/$name/; last lines of $build_dir/$name.log:"
    tail -30 "$build_dir/$name.log"
    status=1
  fi
done
exit $status
