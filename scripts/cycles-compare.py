"""Analysis half of scripts/cycles-compare.sh: reads the renders and times it left in WORK and
prints the comparison table (markdown)."""

import math
import sys
from collections import defaultdict

import numpy as np

import raylab

work, size, depth, threads = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
refs = {name: raylab.read_image(f"{work}/{name}-ref.exr") for name in ("cycles", "raylab")}
# The lamp (radiance 15) and the pixels its edge crosses would dominate any error: a pixel the
# edge cuts is 0 to 15 by where the samples fell. Errors are measured on the rest of the image,
# the light the box receives, which is what a path tracer computes.
lit = (refs["cycles"].max(axis=2) < 1.5) & (refs["raylab"].max(axis=2) < 1.5)


def rel_rmse(image, reference):
    return float(np.sqrt(np.mean((image[lit] - reference[lit]) ** 2)) / np.mean(reference[lit]))
times = defaultdict(list)
errors = defaultdict(list)
with open(f"{work}/times.txt") as f:
    for line in f:
        spp, rep, tc, tr = line.split()
        for name, t in (("cycles", float(tc)), ("raylab", float(tr))):
            image = raylab.read_image(f"{work}/{name}-{spp}-{rep}.exr")
            rel = rel_rmse(image, refs[name])
            times[(name, int(spp))].append(t)
            errors[(name, int(spp))].append(rel)

spps = sorted({spp for _, spp in times})
print(f"Cornell box {size}x{size}, max depth {depth} (Cycles bounces {depth - 1}), {threads} threads, medians of 3;")
print("relative RMSE of each renderer against its own reference, the lamp left out")
print()
print("| spp | Cycles s | raylab s | Cycles Msamples/s | raylab Msamples/s | Cycles rel. RMSE | raylab rel. RMSE |")
print("|---|---|---|---|---|---|---|")
med = lambda v: float(np.median(v))
for spp in spps:
    tc, tr = med(times[("cycles", spp)]), med(times[("raylab", spp)])
    ec, er = med(errors[("cycles", spp)]), med(errors[("raylab", spp)])
    ms = size * size * spp / 1e6
    print(f"| {spp} | {tc:.3f} | {tr:.3f} | {ms / tc:.2f} | {ms / tr:.2f} | {ec:.4f} | {er:.4f} |")


def time_to_reach(name, target):
    # Error falls as 1 / sqrt(time) for an unbiased estimator: fit error^2 * time per renderer on
    # its largest counts and solve for the target.
    spp = spps[-1]
    return med(times[(name, spp)]) * (med(errors[(name, spp)]) / target) ** 2


target = med(errors[("cycles", spps[-1])])
tc, tr = time_to_reach("cycles", target), time_to_reach("raylab", target)
print()
print(f"time to reach Cycles' {spps[-1]}-spp error ({target:.4f}): Cycles {tc:.3f} s, raylab {tr:.3f} s, "
      f"raylab / Cycles = {tr / tc:.2f}")
agree = refs["raylab"][lit].mean(axis=0) / refs["cycles"][lit].mean(axis=0) - 1.0
print(f"references ({lit.sum()} of {lit.size} pixels, the lamp left out): raylab's mean colour is "
      f"{', '.join(f'{a * 100:+.2f}%' for a in agree)} (R, G, B) of Cycles'; relative RMSE between them "
      f"{rel_rmse(refs['raylab'], refs['cycles']):.4f}")
