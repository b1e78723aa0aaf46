#!/usr/bin/env bash
# Installs the Debian packages raylab needs to build, test and benchmark.
# One list; apt-get runs only when something is missing; no prompts (works as root in CI).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  ccache               # compiler cache: rebuilds in CI and in any clone reuse objects
  libgtest-dev libgmock-dev libbenchmark-dev
  libtbb-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev
  libstb-dev libopenexr-dev
  libtinyobjloader-dev libtinygltf-dev
  libembree-dev
  libopenmpi-dev openmpi-bin   # distributed rendering (src/dist/) and its mpirun tests
  clang-format
  clang                # libFuzzer targets (make fuzz)
  python3-jsonschema   # the test that validates shipped scenes against scenes/scene.schema.json
  pybind11-dev python3-dev python3-numpy python3-pytest   # the Python module (python/) and its tests
  # pip install . and the wheel test (pyproject.toml, setup.py, tests/install/wheel_test.sh):
  # the build backend and requirements for --no-build-isolation, venv, pip and python -m build
  python3-setuptools python3-wheel python3-pybind11 python3-venv python3-pip python3-build
  # Debian's libimath-dev exports the PyImath target, whose library ships in python3-imath:
  # without it every configure that finds OpenEXR warns that the file does not exist
  python3-imath
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
