#!/usr/bin/env python3
"""Log-log SVG plots of `raylab compare --json` results against the primitive count.

usage: plot-scaling.py --out DIR RESULT.json ...

For each SPD generator found among the results (the `scene` field, "spd:NAME?size=N"), writes
DIR/scaling-NAME.svg with two panels: primary-ray Mrays/s and build time against primitives, one
line per structure. Prints a Markdown table of the same numbers on stdout.
"""
import argparse
import json
import math
import re
import sys
from collections import defaultdict

COLOURS = {"brute": "#888888", "grid": "#1f77b4", "grid2": "#17becf", "octree": "#2ca02c", "bvh": "#d62728",
           "bvh2": "#ff7f0e", "embree": "#9467bd", "irregular": "#8c564b"}


def load(paths):
    runs = defaultdict(list)  # generator -> [(primitives, structure name, primary Mrays/s, build s)]
    threads = set()
    for path in paths:
        with open(path) as f:
            data = json.load(f)
        m = re.match(r"spd:(\w+)", data["scene"])
        name = m.group(1) if m else data["scene"]
        threads.add(data["threads"])
        for s in data["structures"]:
            if s["skipped"]:
                continue
            runs[name].append((data["primitives"], s["name"], s["rays"]["primary"]["mrays_per_second"],
                               s["build_seconds"]))
    return runs, ", ".join(str(t) for t in sorted(threads))


def log_ticks(lo, hi):
    return [10.0 ** e for e in range(math.floor(math.log10(lo)), math.ceil(math.log10(hi)) + 1)]


def tick_label(v):
    if v >= 1e6:
        return f"{v / 1e6:g}M"
    if v >= 1e3:
        return f"{v / 1e3:g}k"
    return f"{v:g}"


def panel(x0, y0, w, h, series, ylabel, value_index):
    """One log-log panel; series: name -> [(x, y)]."""
    xs = [p[0] for pts in series.values() for p in pts]
    ys = [p[value_index] for pts in series.values() for p in pts if p[value_index] > 0]
    if not xs or not ys:
        return ""
    xt, yt = log_ticks(min(xs), max(xs)), log_ticks(min(ys), max(ys))
    lx0, lx1, ly0, ly1 = math.log10(xt[0]), math.log10(xt[-1]), math.log10(yt[0]), math.log10(yt[-1])
    px = lambda v: x0 + (math.log10(v) - lx0) / max(lx1 - lx0, 1e-9) * w
    py = lambda v: y0 + h - (math.log10(v) - ly0) / max(ly1 - ly0, 1e-9) * h
    out = [f'<rect x="{x0}" y="{y0}" width="{w}" height="{h}" fill="none" stroke="#000"/>']
    for t in xt:
        out.append(f'<line x1="{px(t):.1f}" y1="{y0}" x2="{px(t):.1f}" y2="{y0 + h}" stroke="#ddd"/>')
        out.append(f'<text x="{px(t):.1f}" y="{y0 + h + 16}" text-anchor="middle">{tick_label(t)}</text>')
    for t in yt:
        out.append(f'<line x1="{x0}" y1="{py(t):.1f}" x2="{x0 + w}" y2="{py(t):.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{x0 - 6}" y="{py(t) + 4:.1f}" text-anchor="end">{t:g}</text>')
    out.append(f'<text x="{x0 + w / 2}" y="{y0 + h + 36}" text-anchor="middle">primitives</text>')
    out.append(f'<text x="{x0}" y="{y0 - 8}">{ylabel}</text>')
    for name, pts in series.items():
        pts = sorted(p for p in pts if p[value_index] > 0)
        colour = COLOURS.get(name, "#000")
        path = " ".join(f"{px(p[0]):.1f},{py(p[value_index]):.1f}" for p in pts)
        out.append(f'<polyline points="{path}" fill="none" stroke="{colour}" stroke-width="2"/>')
        for p in pts:
            out.append(f'<circle cx="{px(p[0]):.1f}" cy="{py(p[value_index]):.1f}" r="3" fill="{colour}"/>')
    return "\n".join(out)


def write_svg(path, title, series, threads):
    w, h = 900, 420
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" '
             f'font-size="12">', f'<rect width="{w}" height="{h}" fill="#fff"/>',
             f'<text x="{w / 2}" y="22" text-anchor="middle" font-size="15">{title}</text>',
             panel(70, 60, 330, 290, series, f"primary rays: Mrays/s ({threads} thread{'' if threads == '1' else 's'})", 1),
             panel(520, 60, 330, 290, series, "build time: seconds", 2)]
    for i, name in enumerate(series):
        parts.append(f'<rect x="{70 + i * 110}" y="{h - 22}" width="14" height="4" fill="{COLOURS.get(name, "#000")}"/>')
        parts.append(f'<text x="{90 + i * 110}" y="{h - 16}">{name}</text>')
    parts.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(parts) + "\n")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("results", nargs="+")
    args = ap.parse_args()
    runs, threads = load(args.results)
    for generator, rows in sorted(runs.items()):
        series = defaultdict(list)
        for prims, name, mrays, build in rows:
            series[name].append((prims, mrays, build))
        write_svg(f"{args.out}/scaling-{generator}.svg", f"spd:{generator}: throughput and build time", series,
                  threads)
        names = list(series)
        print(f"\n### spd:{generator}\n")
        print("| primitives | " + " | ".join(f"{n} Mrays/s" for n in names) + " | " +
              " | ".join(f"{n} build s" for n in names) + " |")
        print("|---:|" + "---:|" * (2 * len(names)))
        for prims in sorted({r[0] for r in rows}):
            cells = {n: next(((m, b) for p, m, b in series[n] if p == prims), None) for n in names}
            mr = " | ".join(f"{c[0]:.3g}" if c else "–" for c in cells.values())
            bs = " | ".join(f"{c[1]:.3g}" if c else "–" for c in cells.values())
            print(f"| {prims:,} | {mr} | {bs} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
