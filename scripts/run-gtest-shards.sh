#!/usr/bin/env bash
# Runs a GoogleTest binary in SHARDS processes at once (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX),
# from DIR, with an optional GTEST_FILTER, and fails when any shard fails, printing that shard's
# output. Used for the sanitizer stage of CI, where one process per test (ctest's way, through
# gtest_discover_tests) costs half a second of sanitizer start-up each, a third of the stage.
#   usage: run-gtest-shards.sh BINARY DIR SHARDS [FILTER]
set -uo pipefail
if [ $# -lt 3 ]; then
  echo "usage: $0 BINARY DIR SHARDS [FILTER]" >&2
  exit 2
fi
binary=$(realpath "$1")
dir=$2
shards=$3
filter=${4:-*}
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
pids=()
for ((i = 0; i < shards; ++i)); do
  (cd "$dir" && GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$binary" --gtest_filter="$filter" \
    --gtest_brief=1 >"$logs/$i.log" 2>&1) &
  pids+=($!)
done
status=0
for ((i = 0; i < shards; ++i)); do
  if wait "${pids[$i]}"; then
    echo "shard $i of $shards: $(grep -E '^\[  PASSED  \]' "$logs/$i.log" || echo 'passed')"
  else
    echo "shard $i of $shards FAILED; its output:"
    cat "$logs/$i.log"
    status=1
  fi
done
exit $status
