#!/usr/bin/env bash
# The installed C++ package works (ctest test `install`, label `install`): `cmake --install` into
# a fresh prefix installs the public headers and nothing private, each installed header compiles
# on its own, examples/cpp configures with find_package(raylab) against the prefix, builds and
# runs, and the installed raylab runs with a clean environment, also after the prefix is moved.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR CXX
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
cxx=$3
tmp=$(mktemp -d "${TMPDIR:-/tmp}/raylab-install.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

# step, fail, logged
source "$(dirname "${BASH_SOURCE[0]}")/script_steps.sh"

version=$(sed -n 's/^#define RAYLAB_VERSION_STRING "\(.*\)"$/\1/p' "$build/include/raylab/version.h")
libdir=$(sed -n 's/^CMAKE_INSTALL_LIBDIR:[A-Z]*=//p' "$build/CMakeCache.txt")
# The exported targets' per-configuration file is named after the build type (noconfig if none).
config=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt" | tr '[:upper:]' '[:lower:]')
[[ -n "$version" && -n "$libdir" ]] || fail "no version or libdir in $build"
# The Python module, when this build has it: its folder under the prefix and its interpreter.
pydir=""
if grep -q '^RAYLAB_BUILD_PYTHON:BOOL=ON' "$build/CMakeCache.txt"; then
  pydir=$(sed -n 's/^RAYLAB_PYTHON_INSTALL_DIR:[A-Z]*=//p' "$build/CMakeCache.txt")
  python=$(sed -n 's/^RAYLAB_PYTHON:[A-Z]*=//p' "$build/CMakeCache.txt")
fi

step "cmake --install into a fresh prefix"
logged "$tmp/install.log" "cmake --install failed" cmake --install "$build" --prefix "$prefix"

step "installed files"
# The headers are include/raylab of the source tree plus the generated version.h: no more, no less.
want=$( (cd "$source/include" && find raylab -name '*.h' && echo raylab/version.h) | sort)
got=$(cd "$prefix/include" && find . -type f -o -type l | sed 's|^\./||' | sort)
[ "$want" = "$got" ] || {
  diff <(echo "$want") <(echo "$got") >&2 || true
  fail "the installed headers are not exactly include/raylab (< source, > installed)"
}
while read -r private; do
  [ ! -e "$prefix/include/raylab/${private#src/}" ] || fail "private header $private was installed"
done < <(cd "$source" && find src -name '*.h')
# Beside the headers: the two libraries with their SONAME links, the MPI module where MPI was
# found, the package files, the program.
others=$(cd "$prefix" && find . -type f -o -type l | sed 's|^\./||' | grep -v '^include/raylab/' | sort)
expected_others=$(
  for lib in raylab raylab_dist; do
    printf '%s\n' "$libdir/lib$lib.so" "$libdir/lib$lib.so.0" "$libdir/lib$lib.so.$version"
  done
  for f in raylabConfig raylabConfigVersion raylabTargets "raylabTargets-${config:-noconfig}"; do
    echo "$libdir/cmake/raylab/$f.cmake"
  done
  echo bin/raylab
  # The modules beside the libraries, which libraylab and libraylab_dist load from their folder.
  echo "$libdir/libraylab_exr.so"
  [ ! -e "$build/$libdir/libraylab_embree.so" ] || echo "$libdir/libraylab_embree.so"
  [ ! -e "$build/$libdir/libraylab_mpi.so" ] || echo "$libdir/libraylab_mpi.so"
  if [ -n "$pydir" ]; then
    for f in __init__.py __init__.pyi py.typed _build.py _cpu_check.py; do echo "$pydir/raylab/$f"; done
    (cd "$build/python/raylab" && ls _raylab*.so | sed "s|^|$pydir/raylab/|")
  fi
)
[ "$others" = "$(sort <<<"$expected_others")" ] || {
  diff <(sort <<<"$expected_others") <(echo "$others") >&2 || true
  fail "unexpected installed files (< expected, > installed)"
}
[ "$(readlink "$prefix/$libdir/libraylab.so.0")" = "libraylab.so.$version" ] || fail "libraylab.so.0 link"
targets_file=$prefix/$libdir/cmake/raylab/raylabTargets.cmake
for target in raylab::raylab raylab::dist; do
  grep -q "add_library($target SHARED IMPORTED)" "$targets_file" || fail "$target is not exported"
done

step "public headers include only the standard library and each other"
third_party=$(grep -rhoE '^\s*#\s*include\s*<[^>]+>' "$prefix/include" | sed -E 's/.*<([^>]+)>.*/\1/' | sort -u |
  grep -Ev '^([a-z_0-9]+|immintrin\.h)$' || true)
[ -z "$third_party" ] || fail "public headers include third-party headers: $third_party"
quoted=$(grep -rhoE '^\s*#\s*include\s*"[^"]+"' "$prefix/include" | grep -v '"raylab/' || true)
[ -z "$quoted" ] || fail "public headers include non-raylab headers: $quoted"

# The flags a program gets from raylab::raylab (none today: see docs/architecture.md, "The
# installed package"), read from the exported targets so that this stays true if that changes.
read -ra interface_flags <<<"$(sed -n 's/^ *INTERFACE_COMPILE_OPTIONS "\(.*\)"$/\1/p' "$targets_file" | tr ';' ' ')"
read -ra interface_defs <<<"$(sed -n 's/^ *INTERFACE_COMPILE_DEFINITIONS "\(.*\)"$/\1/p' "$targets_file" | tr ';' '\n' |
  sed '/^$/d; s/^/-D/' | tr '\n' ' ')"
headers=$(cd "$prefix/include" && find raylab -name '*.h' | sort)
check=("$cxx" -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror "${interface_flags[@]}" "${interface_defs[@]}")
step "each of $(wc -l <<<"$headers") installed headers compiles on its own: ${check[*]}"
# About a second of compiler per header (a minute on two idle cores): skipped when the compiler,
# the command and every header are the same as at the last success (the stamp in the build tree).
stamp=$build/tests/install_headers.stamp
key=$( (
  "$cxx" --version
  echo "${check[*]}"
  cd "$prefix/include" && xargs sha256sum <<<"$headers"
) | sha256sum | cut -d' ' -f1)
if [[ -f $stamp && $(cat "$stamp") == "$key" ]]; then
  echo "headers: unchanged since the last check (remove $stamp to check again)"
else
  mkdir "$tmp/headers"
  while read -r header; do
    printf '#include <%s>\n' "$header" >"$tmp/headers/$(tr '/.' '__' <<<"$header").cpp"
  done <<<"$headers"
  headers_start=$SECONDS
  find "$tmp/headers" -name '*.cpp' -print0 | xargs -0 -P 2 -n 8 "${check[@]}" -I"$prefix/include" ||
    fail "an installed header does not compile on its own"
  echo "$key" >"$stamp"
  echo "headers: $((SECONDS - headers_start)) s"
fi

step "examples/cpp with find_package(raylab) against the prefix"
logged "$tmp/examples-configure.log" "examples/cpp does not configure" \
  cmake -S "$source/examples/cpp" -B "$tmp/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix"
grep -qx "raylab_DIR:PATH=$prefix/$libdir/cmake/raylab" "$tmp/examples/CMakeCache.txt" ||
  fail "find_package found another raylab: $(grep '^raylab_DIR' "$tmp/examples/CMakeCache.txt")"
examples=(render_scene cast_rays)
logged "$tmp/examples-build.log" "examples/cpp does not build" cmake --build "$tmp/examples" -j 2 --target "${examples[@]}"

step "render_scene demo at 64 x 48"
"$tmp/examples/render_scene" demo "$tmp/demo.png" 64 48
[ "$(head -c 8 "$tmp/demo.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "demo.png is not a PNG"
# IHDR: width and height, big-endian, at bytes 16 and 20.
size=$(od -An -tu1 -j16 -N8 "$tmp/demo.png" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 "x" $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }')
[ "$size" = 64x48 ] || fail "demo.png is $size, not 64x48"

step "cast_rays on the built-in quad and on scenes/meshes/torus.obj"
quad=$("$tmp/examples/cast_rays")
echo "$quad"
grep -q "^hits: *65536 of 65536" <<<"$quad" || fail "not every ray hit the quad"
grep -q "^distinct primitives hit: 2 of 2" <<<"$quad" || fail "the quad's two triangles were not both hit"
torus=$("$tmp/examples/cast_rays" "$source/scenes/meshes/torus.obj" 64)
echo "$torus"
grep -qE "^hits: *[1-9][0-9]* of 4096" <<<"$torus" || fail "no ray hit the torus"

step "the installed raylab runs with no LD_LIBRARY_PATH, from its prefix and from a moved copy"
for f in "$prefix/bin/raylab" "$prefix/$libdir"/libraylab*.so."$version"; do
  ! readelf -d "$f" | grep -F "$build" || fail "$f keeps a path into the build tree"
done
readelf -d "$prefix/bin/raylab" | grep -qF "[\$ORIGIN/../$libdir]" || fail "bin/raylab has no \$ORIGIN/../$libdir RUNPATH"
[ "$(env -i "$prefix/bin/raylab" --version | head -n 1)" = "raylab $version" ] || fail "installed raylab --version"
# The installed module, with nothing but PYTHONPATH: it finds libraylab.so by its RUNPATH.
import_check='import raylab, numpy as np
s = raylab.Mesh(np.float32([[0, 0, 0], [1, 0, 0], [0, 1, 0]]), np.uint32([[0, 1, 2]]))
h = s.intersect(np.float32([[0.2, 0.2, 1, 0, 0, -1]]))
assert h["prim_id"][0] == 0 and h["t"][0] == 1, h
print("python: raylab", raylab.__version__)'
if [ -n "$pydir" ]; then
  step "the installed Python module imports and answers with only PYTHONPATH set"
  env -i PYTHONPATH="$prefix/$pydir" "$python" -c "$import_check" || fail "installed module"
fi
# Every instruction set this CPU runs, forced by RAYLAB_ISA: the installed program says it uses
# it and renders the same bytes, and the installed module reports it and answers.
sets=$(env -i "$prefix/bin/raylab" --version | sed -n 's/.*this CPU: \(.*\))$/\1/p' | tr -d ,)
[ -n "$sets" ] || fail "raylab --version names no instruction set"
step "each instruction set ($sets) forced: the installed program and module"
for set in $sets; do
  env -i RAYLAB_ISA="$set" "$prefix/bin/raylab" --version | grep -q "^kernels: $set " || fail "RAYLAB_ISA=$set not taken"
  env -i RAYLAB_ISA="$set" "$prefix/bin/raylab" render demo --width 48 --height 32 -q -o "$tmp/demo-$set.pfm" ||
    fail "render with RAYLAB_ISA=$set"
  cmp "$tmp/demo-${sets%% *}.pfm" "$tmp/demo-$set.pfm" || fail "RAYLAB_ISA=$set renders other bytes"
  if [ -n "$pydir" ]; then
    env -i RAYLAB_ISA="$set" PYTHONPATH="$prefix/$pydir" "$python" -c "$import_check
assert raylab.isa() == '$set', raylab.isa()" || fail "installed module with RAYLAB_ISA=$set"
  fi
done
mv "$prefix" "$tmp/moved"
[ "$(env -i "$tmp/moved/bin/raylab" --version | head -n 1)" = "raylab $version" ] || fail "moved raylab --version"
if [ -n "$pydir" ]; then
  env -i PYTHONPATH="$tmp/moved/$pydir" "$python" -c "$import_check" || fail "moved module"
fi

echo "install test: ok in $((SECONDS - script_start)) s"
