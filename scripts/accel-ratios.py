#!/usr/bin/env python3
"""Every structure against the reference on many scenes, as ratios (docs/accelerators.md).

usage: accel-ratios.py RESULT.json ...   (each written by `raylab compare ... --json FILE`)

Prints one Markdown table per structure other than the reference: for each scene, its Mrays/s
over the reference's (primary / shadow / diffuse), its build time over the reference's, and its
bytes per primitive over the reference's, all from the same `raylab compare` run; and a last row
with the lowest ratio of each column (the one the issue's bars are about). Ratios below the bars
given with --bars (e.g. `irregular=0.8,0.6,0.6` for primary, shadow, diffuse) are marked with *.
"""
import argparse
import json
import os
import sys


def load(paths):
    runs = []
    for path in paths:
        with open(path) as f:
            runs.append(json.load(f))
    return runs


def scene_label(scene):
    return os.path.basename(scene) if "/" in scene else scene


def parse_bars(items):
    bars = {}
    for item in items or []:
        name, _, values = item.partition("=")
        bars[name] = [float(v) for v in values.split(",")]
    return bars


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("results", nargs="+")
    parser.add_argument("--bars", nargs="*", help="NAME=PRIMARY,SHADOW,DIFFUSE minimum ratios")
    args = parser.parse_args()
    runs = load(args.results)
    bars = parse_bars(args.bars)
    names = []
    for run in runs:
        for s in run["structures"]:
            if s["name"] != run["reference"] and s["name"] not in names:
                names.append(s["name"])
    kinds = ("primary", "shadow", "diffuse")
    for name in names:
        limit = bars.get(name, [0.0, 0.0, 0.0])
        print(f"\n**{name}** against {runs[0]['reference']} (ratio of Mrays/s; build and memory: ratio of ms "
              "and of bytes per primitive, lower is better)\n")
        print("| scene | primitives | primary | shadow | diffuse | build | memory |")
        print("|---|---:|---:|---:|---:|---:|---:|")
        lowest = [float("inf")] * 3
        highest = [0.0, 0.0]
        for run in runs:
            by_name = {s["name"]: s for s in run["structures"] if not s["skipped"]}
            ref, s = by_name.get(run["reference"]), by_name.get(name)
            if ref is None or s is None:
                continue
            cells = []
            for i, kind in enumerate(kinds):
                r = s["rays"][kind]["mrays_per_second"] / ref["rays"][kind]["mrays_per_second"]
                lowest[i] = min(lowest[i], r)
                cells.append(f"{r:.2f}{'*' if r < limit[i] else ''}")
            build = s["build_seconds"] / ref["build_seconds"]
            memory = s["bytes_per_primitive"] / ref["bytes_per_primitive"]
            highest = [max(highest[0], build), max(highest[1], memory)]
            agreed = "" if s["mismatches"] == 0 else f" ({s['mismatches']} mismatches)"
            print(f"| {scene_label(run['scene'])}{agreed} | {run['primitives']} | {' | '.join(cells)} | "
                  f"{build:.2f} | {memory:.2f} |")
        print(f"| **worst** | | {' | '.join(f'{v:.2f}' for v in lowest)} | {highest[0]:.2f} | {highest[1]:.2f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
