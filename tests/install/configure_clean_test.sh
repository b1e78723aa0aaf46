#!/usr/bin/env bash
# A newcomer's configure is clean (ctest test `configure_clean`, label `install`): `cmake --preset
# release` in a fresh build folder prints no warning. Debian's libimath-dev, found through
# OpenEXR, warned of a missing PyImath library until install-deps.sh installed python3-imath.
# Usage: configure_clean_test.sh SOURCE_DIR
set -euo pipefail
source=$(cd "$1" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/raylab-configure.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
cmake -S "$source" --preset release -B "$tmp/build" >"$tmp/configure.log" 2>&1 || {
  cat "$tmp/configure.log"
  echo "FAIL: cmake --preset release does not configure" >&2
  exit 1
}
if grep -n -i -E "warning|does not exist|deprecat" "$tmp/configure.log"; then
  echo "FAIL: cmake --preset release printed the above (whole output in the log below)" >&2
  cat "$tmp/configure.log" >&2
  exit 1
fi
echo "configure: clean, $(wc -l <"$tmp/configure.log") lines"
