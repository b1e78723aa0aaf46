#!/usr/bin/env bash
# Runs every libFuzzer target in BUILD_DIR/bin for SECONDS each (make fuzz).
# Seeds come from fuzz/corpus/NAME; the growing corpus and any crash input stay under BUILD_DIR.
set -euo pipefail
build_dir=${1:?usage: fuzz.sh BUILD_DIR SECONDS}
seconds=${2:-60}
root=$(cd "$(dirname "$0")/.." && pwd)
status=0
shopt -s nullglob
targets=("$build_dir"/bin/*_fuzz)
if [ ${#targets[@]} -eq 0 ]; then
  echo "fuzz: no targets in $build_dir/bin (configure with the fuzz preset)"
  exit 1
fi
for target in "${targets[@]}"; do
  name=$(basename "$target" _fuzz)
  work="$build_dir/corpus/$name"
  artifacts="$build_dir/artifacts/$name/"
  mkdir -p "$work" "$artifacts"
  seeds=()
  [ -d "$root/fuzz/corpus/$name" ] && seeds=("$root/fuzz/corpus/$name")
  echo "fuzz: $name for ${seconds}s"
  if ! "$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
      -artifact_prefix="$artifacts" -print_final_stats=1 "$work" "${seeds[@]}" >"$build_dir/$name.log" 2>&1; then
    echo "fuzz: $name FAILED; input saved in $artifacts; last lines of $build_dir/$name.log:"
    tail -30 "$build_dir/$name.log"
    status=1
  else
    grep -E "^stat::number_of_executed_units|^stat::peak_rss_mb" "$build_dir/$name.log" | tr '\n' ' '
    echo
  fi
done
exit $status
