#!/usr/bin/env bash
# Renders the path-traced Cornell box reference of tests/render/cornell_reference_test.cpp: 16x16
# pixels, max depth 6, as 64 renders of 1024 independent (random sampler) samples per pixel with
# seeds 1000 to 1063 (the test renders with seeds below 100). Their mean, 65536 samples per
# pixel, goes to tests/data/cornell-path-16x16.pfm; the variance of one sample, per pixel and
# channel (1024 times the variance of the 64 means), to cornell-path-16x16-variance.pfm: what
# the test's z-test divides by. Run it again only when the path integrator's expected value
# changes on purpose (a new material mapping, a changed light rule), and say why in the commit.
#   usage: scripts/make-cornell-reference.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for seed in $(seq 1000 1063); do
  "$build/bin/raylab" render cornell --integrator path --width 16 --height 16 --spp 1024 --sampler random \
    --max-depth 6 --seed "$seed" --threads 2 --quiet -o "$work/$seed.pfm"
done
PYTHONPATH="$build/python" /usr/bin/python3 - "$work" <<'PY'
import glob
import sys

import numpy as np

import raylab

batches = np.array([raylab.read_image(f) for f in sorted(glob.glob(sys.argv[1] + "/*.pfm"))])
raylab.write_image("tests/data/cornell-path-16x16.pfm", batches.mean(axis=0))
raylab.write_image("tests/data/cornell-path-16x16-variance.pfm", 1024.0 * batches.var(axis=0, ddof=1))
print(f"{len(batches)} batches; mean radiance {batches.mean():.5f}")
PY
