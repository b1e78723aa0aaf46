#!/usr/bin/env bash
# The run paths of the build tree's programs and libraries (CMakeLists.txt): no empty entry,
# which the dynamic loader reads as the current directory and searches for every library it
# loads. CMake pads the build run path with empty entries when it must be rewritten at install;
# the programs and libraries are built with their installed run path instead.
# usage: build_run_paths_test.sh FILE...
set -euo pipefail
[ $# -gt 0 ] || { echo "usage: $0 FILE..." >&2; exit 2; }
status=0
for elf in "$@"; do
  runpath=$(readelf -d "$elf" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p')
  [ -n "$runpath" ] || { echo "FAIL: $elf has no run path" >&2; status=1; continue; }
  # An empty entry: the whole is empty, or it starts or ends with ':', or holds '::'.
  case ":$runpath:" in
    *::*) echo "FAIL: $elf has run path '$runpath', with an empty entry" >&2; status=1 ;;
    *) echo "ok: $elf: $runpath" ;;
  esac
done
exit $status
