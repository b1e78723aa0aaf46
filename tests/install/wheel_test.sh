#!/usr/bin/env bash
# The Python package as pip installs it (ctest test `python_wheel`, labels install and python):
# a wheel built offline from a clean copy of the source holds only what it should, installs into
# a new virtual environment, and from outside the source tree the Python suite passes against it,
# the `raylab` command it brings runs (and renders the same bytes as the build tree's at every
# instruction set), and `pip uninstall` leaves the environment as it was.
# Usage: wheel_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
source=$(cd "$2" && pwd)
tmp=$(mktemp -d "${TMPDIR:-/tmp}/raylab-wheel.XXXXXX")
trap 'rm -rf "$tmp"' EXIT

# step, fail, logged
source "$(dirname "${BASH_SOURCE[0]}")/script_steps.sh"
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }

python=$(cache_value RAYLAB_PYTHON)
version=$(sed -n 's/^#define RAYLAB_VERSION_STRING "\(.*\)"$/\1/p' "$build/include/raylab/version.h")
[[ -n "$python" && -n "$version" ]] || fail "no RAYLAB_PYTHON or version in $build"
# pip offline and on its own: no index, no cache or configuration of this user's.
export PIP_NO_INDEX=1 PIP_CACHE_DIR=$tmp/pip-cache PIP_CONFIG_FILE=/dev/null PIP_DISABLE_PIP_VERSION_CHECK=1
unset PYTHONPATH

step "a clean copy of the source"
# The files git knows (tracked, and new ones it does not ignore) as they are in the working tree:
# no build folder and nothing else ignored can leak into the wheel.
copy=$tmp/src
mkdir "$copy"
if git -C "$source" rev-parse --git-dir >/dev/null 2>&1; then
  git -C "$source" ls-files -z --cached --others --exclude-standard |
    tar -C "$source" --null -T - --ignore-failed-read -cf - 2>/dev/null | tar -C "$copy" -xf -
else
  tar -C "$source" --exclude=./build -cf - . | tar -C "$copy" -xf -
fi
[ ! -e "$copy/build" ] || fail "the copy has a build folder"

step "the source distribution (python3 -m build --sdist --no-isolation)"
logged "$tmp/sdist.log" "the source distribution does not build" \
  "$python" -m build --sdist --no-isolation -o "$tmp/dist" "$copy"
sdist=$tmp/dist/raylab-$version.tar.gz
[ -f "$sdist" ] || fail "no $sdist"
! tar tzf "$sdist" | grep -E "^raylab-$version/(build|tests|bench|fuzz|python/tests)/" || fail "the sdist holds the above"

step "pip wheel --no-build-isolation (offline) from the source distribution, with $python"
# Built from the sdist, so that the sdist is shown to hold all the build reads. The build's own
# warning flag, so that the compiler cache (CMakeLists.txt: base_dir is the source folder) finds
# the objects the build tree compiled with the same flags.
export RAYLAB_CMAKE_ARGS="-DRAYLAB_WERROR=$(cache_value RAYLAB_WERROR)"
logged "$tmp/wheel.log" "the wheel does not build" \
  "$python" -m pip wheel --no-build-isolation --no-deps -w "$tmp/dist" "$sdist"
wheels=("$tmp"/dist/raylab-*.whl)
[ ${#wheels[@]} -eq 1 ] || fail "expected one wheel, got: ${wheels[*]}"
wheel=${wheels[0]}
echo "wheel: $(basename "$wheel"), $(($(stat -c %s "$wheel") / 1024)) KiB"

step "the wheel holds the package and its metadata, nothing else"
"$python" - "$wheel" "$version" "$copy" "$source" "$build" <<'EOF' || fail "the wheel's contents"
import sys, sysconfig, zipfile

wheel, version, *build_paths = sys.argv[1:]
suffix = sysconfig.get_config_var("EXT_SUFFIX")
info = f"raylab-{version}.dist-info"
package = ["__init__.py", "__init__.pyi", "py.typed", "_build.py", "_command.py", "_cpu_check.py",
           f"_raylab{suffix}", "lib/libraylab.so.0", "lib/libraylab_dist.so.0", "lib/libraylab_exr.so",
           "lib/libraylab_embree.so", "bin/raylab"]
expected = {f"raylab/{name}" for name in package}
expected |= {f"{info}/{name}" for name in ("METADATA", "WHEEL", "RECORD", "entry_points.txt", "top_level.txt")}
with zipfile.ZipFile(wheel) as archive:
    names = set(archive.namelist())
    if names != expected:
        sys.exit(f"unexpected files: {sorted(names - expected)}; missing: {sorted(expected - names)}")
    mode = archive.getinfo("raylab/bin/raylab").external_attr >> 16
    if not mode & 0o111:
        sys.exit(f"raylab/bin/raylab is not executable in the wheel (mode {mode:o})")
    metadata = archive.read(f"{info}/METADATA").decode()
    if f"\nVersion: {version}\n" not in metadata:
        sys.exit(f"METADATA does not say Version: {version}")
    if "Requires-Dist: numpy" not in metadata:
        sys.exit("METADATA does not require numpy")
    if "raylab = raylab._command:main" not in archive.read(f"{info}/entry_points.txt").decode():
        sys.exit("no raylab console script")
    for name in names:
        if name.startswith(info):
            text = archive.read(name).decode()
            for path in build_paths + ["/tmp/", "pip-req-build"]:
                if path in text:
                    sys.exit(f"{name} holds the build machine's path {path}")
print(f"{len(names)} files, as expected")
EOF
# The run paths are relative to the files themselves ($ORIGIN): none names this machine's folders.
mkdir "$tmp/unpacked"
"$python" -m zipfile -e "$wheel" "$tmp/unpacked"
for elf in "$tmp"/unpacked/raylab/_raylab*.so "$tmp"/unpacked/raylab/lib/*.so* "$tmp"/unpacked/raylab/bin/raylab; do
  runpath=$(readelf -d "$elf" | sed -n 's/.*(RUNPATH).*\[\(.*\)\]/\1/p')
  [[ $runpath == \$ORIGIN* && $runpath != *:* ]] || fail "$elf has run path '$runpath', not one relative to \$ORIGIN"
done

step "a new virtual environment (--system-site-packages, for Debian's numpy and pytest)"
venv=$tmp/venv
"$python" -m venv --system-site-packages "$venv"
snapshot() { (cd "$venv" && find . | LC_ALL=C sort); }
snapshot >"$tmp/venv-before.txt"
logged "$tmp/install.log" "pip install of the wheel failed" "$venv/bin/python" -m pip install "$wheel"

step "from outside the source tree: the installed package is the one imported"
outside=$tmp/outside
mkdir "$outside"
cd "$outside"
"$venv/bin/python" - "$venv" "$version" <<'EOF' || fail "the installed package"
import importlib.metadata, pathlib, sys
import raylab

venv, version = sys.argv[1:]
where = pathlib.Path(raylab.__file__).resolve()
assert where.is_relative_to(pathlib.Path(venv).resolve()), f"raylab imported from {where}"
assert raylab.__version__ == version == importlib.metadata.version("raylab"), raylab.__version__
print(f"raylab {raylab.__version__} from {where.parent}")
EOF

step "the Python suite against the installed package"
RAYLAB_EXPECT_PACKAGE_UNDER=$venv RAYLAB_SOURCE_DIR=$source RAYLAB_BINARY=$venv/bin/raylab \
  "$venv/bin/python" -m pytest -q -p no:cacheprovider "$copy/python/tests" || fail "the Python suite against the wheel"

step "the raylab command the wheel brings"
# Only the environment's bin on PATH beside the system's: no LD_LIBRARY_PATH, no build tree.
run_installed_from() {
  local environment=$1
  shift
  env -i PATH="$environment/bin:/usr/bin:/bin" "$@"
}
run_installed() { run_installed_from "$venv" "$@"; }
[ "$(run_installed raylab --version | head -n 1)" = "raylab $version" ] || fail "installed raylab --version"
run_installed raylab render demo --width 64 --height 48 -q -o "$outside/demo.png" || fail "installed raylab render"
[ "$(head -c 8 "$outside/demo.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] || fail "demo.png is not a PNG"
set +e
run_installed raylab render "$outside/absent.nff" -q -o "$outside/x.png" 2>"$outside/err.txt"
status=$?
set -e
[ $status -eq 1 ] && grep -q "absent.nff" "$outside/err.txt" || fail "a missing scene gave exit $status, not 1 naming the file"

sets=$(run_installed raylab --version | sed -n 's/.*this CPU: \(.*\))$/\1/p' | tr -d ,)
[ -n "$sets" ] || fail "raylab --version names no instruction set"
step "each instruction set ($sets) forced: the same bytes as the build tree's raylab, and the module"
for set in $sets; do
  run_installed RAYLAB_ISA="$set" raylab --version | grep -q "^kernels: $set " || fail "RAYLAB_ISA=$set not taken"
  run_installed RAYLAB_ISA="$set" raylab render demo --width 48 --height 32 -q -o "$outside/wheel-$set.pfm"
  # The wheel is built with the release preset (baseline x86-64): a build tree compiled for
  # another level may round differently outside the kernels, so only the same level compares.
  if [ "$(cache_value RAYLAB_ARCH)" = x86-64 ]; then
    env -i RAYLAB_ISA="$set" "$build/bin/raylab" render demo --width 48 --height 32 -q -o "$outside/build-$set.pfm"
    cmp "$outside/build-$set.pfm" "$outside/wheel-$set.pfm" || fail "RAYLAB_ISA=$set: the wheel's raylab renders other bytes"
  fi
  run_installed RAYLAB_ISA="$set" "$venv/bin/python" -c "import raylab; assert raylab.isa() == '$set', raylab.isa()" ||
    fail "the installed module with RAYLAB_ISA=$set"
done

step "pip uninstall leaves the environment as it was"
logged "$tmp/uninstall.log" "pip uninstall failed" "$venv/bin/python" -m pip uninstall -y raylab
snapshot >"$tmp/venv-after.txt"
diff "$tmp/venv-before.txt" "$tmp/venv-after.txt" >&2 || fail "pip uninstall left files behind (> above)"

step "an editable install (pip install -e) of the copy"
# The extension, the library and the command are copied back into the copy's python/raylab.
editable=$tmp/editable
"$python" -m venv --system-site-packages "$editable"
(cd "$copy" && logged "$tmp/editable.log" "pip install -e failed" \
  "$editable/bin/python" -m pip install --no-build-isolation -e .)
"$editable/bin/python" -c "import raylab; print(raylab.__file__); assert raylab.render" | grep -qx "$copy/python/raylab/__init__.py" ||
  fail "the editable install does not import from $copy/python/raylab"
[ "$(run_installed_from "$editable" raylab --version | head -n 1)" = "raylab $version" ] || fail "editable raylab --version"

echo "wheel test: ok in $((SECONDS - script_start)) s"
