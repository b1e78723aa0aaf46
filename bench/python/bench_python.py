#!/usr/bin/env python3
"""The raylab Python module against `raylab bench` (our C++ BVH and Embree 3) on the same rays.

Issue 20's speed table. For each scene, thread count and ray kind it runs `raylab bench` (which
builds our BVH and an Embree scene, generates the rays, checks the two agree and times both),
has it write its rays and its closest hits, then loads the same scene with `raylab.load(path,
allow_outside_paths=True)` (the same loader and options, so the same primitive ids), checks that
`Scene.intersect` gives the same hits and times it on exactly those rays, read in place from the
.rays records, twice: with all five answers (the default) and with `fields=["t", "prim_id"]`
(the two answers `raylab bench` writes). The build is timed from
numpy arrays (`raylab.Mesh(vertices, triangles).build("bvh")`) against `raylab bench`'s build of
the same mesh file. The gap between the module and the C++ figures is split into its causes:
`raylab_query_overhead` (bench/python/query_overhead.cpp, beside the command line in the build)
times the C++ call behind Scene.intersect with and without its extra answers, and a child
process times the module with glibc told to keep freed memory (see python_pages_kept).

The whole sequence runs --rounds times and each figure is the median over the rounds, because
the machines this runs on are shared. The rays' limits are checked ray by ray: one tmin and
tmax shared by every ray are passed as numbers, per-ray limits as the records' tmin and tmax
columns (arrays of the rays' leading shape), and the table's notes say which.

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python/bench_python.py \\
        --binary build/release/bin/raylab [--repeats 3] [--rounds 3] [--quick] [--json FILE]

Only numpy is needed beyond the standard library and the module.
"""

import argparse
import datetime
import functools
import json
import os
import pathlib
import platform
import shlex
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import raylab

ROOT = pathlib.Path(__file__).resolve().parents[2]

# The scenes of the ray figures, as raylab bench is given them (relative to the project root).
RAY_SCENES = (
    ("bunny", "bench/scenes/bunny-on-ground-triangles.json"),
    ("igea", "../shared/scenes/igea.ply"),
)
# The meshes of the build figure: files whose arrays numpy can read here.
BUILD_MESHES = (
    ("bunny", "../shared/scenes/stanford-bunny.obj"),
    ("igea", "../shared/scenes/igea.ply"),
)
RAY_KINDS = ("primary", "diffuse")

# The answers of the second Python figure: those raylab bench writes (its .hits records).
HIT_FIELDS = ("t", "prim_id")

# The bars.
BAR_VS_CPP = 0.9  # Python intersect at least this fraction of raylab's C++ throughput
BAR_VS_EMBREE_PRIMARY = 1.0  # on primary rays, at least Embree's single-ray throughput
BAR_BUILD = 1.1  # build from numpy arrays at most this multiple of the C++ build time

RAY_DTYPE = np.dtype("<f4")  # a .rays record: 8 of these (origin xyz, tmin, direction xyz, tmax)
HIT_DTYPE = np.dtype([("t", "<f4"), ("prim", "<u4")])  # a .hits record


def log(message):
    """Progress on stderr, so that stdout holds only the tables."""
    print(f"bench_python: {message}", file=sys.stderr, flush=True)


def parse_args():
    """The command line."""
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--binary", default="build/release/bin/raylab", help="the raylab command line (default: %(default)s)")
    p.add_argument("--repeats", type=int, default=3, help="timed runs of each figure, median kept (default: 3)")
    p.add_argument("--rounds", type=int, default=3,
                   help="times the whole sequence (raylab bench, then the module) runs; each figure is the median "
                   "over the rounds of the per-round medians, which evens out a shared machine's load (default: 3)")
    p.add_argument("--threads", type=int, nargs="+", default=[1, 2], help="thread counts (default: 1 2)")
    p.add_argument("--scenes", nargs="+", choices=[n for n, _ in RAY_SCENES], default=[n for n, _ in RAY_SCENES],
                   help="scenes of the ray and build figures (default: all)")
    p.add_argument("--quick", action="store_true",
                   help="a smoke run: 256x192 primary rays, one repeat, one round, one thread")
    p.add_argument("--width", type=int, default=1024, help="primary rays per row (default: 1024, as raylab bench)")
    p.add_argument("--height", type=int, default=768, help="rows of primary rays (default: 768)")
    p.add_argument("--json", metavar="FILE", help="also write every figure and command as JSON")
    p.add_argument("--workdir", help="keep the .rays, .hits and JSON files of raylab bench here (default: a "
                   "temporary folder, removed at the end)")
    args = p.parse_args()
    if args.quick:
        args.width, args.height, args.repeats, args.rounds, args.threads = 256, 192, 1, 1, [1]
    if min(args.repeats, args.rounds, *args.threads) < 1:
        p.error("--repeats, --rounds and --threads must be at least 1")
    args.binary = str(pathlib.Path(args.binary).resolve())
    if not os.access(args.binary, os.X_OK):
        p.error(f"--binary {args.binary}: not an executable (build it first: cmake --build build/release)")
    return args


def run(command, what):
    """Runs `command` in the project root; its stdout, or SystemExit with its stderr on failure."""
    log(f"{what}: {shlex.join(command)}")
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True)
    if done.returncode != 0:
        raise SystemExit(f"bench_python: {what} failed (exit {done.returncode}):\n{done.stderr}")
    return done.stdout


def cpp_bench(binary, scene, kind, threads, repeats, width, height, out_dir, purpose="rays"):
    """Runs `raylab bench` on one ray kind; its JSON report, the command and the .rays/.hits paths."""
    stem = out_dir / f"{pathlib.Path(scene).stem}-{purpose}-{kind}-t{threads}"
    paths = {ext: str(stem) + "." + ext for ext in ("json", "rays", "hits")}
    command = [binary, "bench", scene, "--rays", kind, "--threads", str(threads), "--repeats", str(repeats),
               "--width", str(width), "--height", str(height), "--json", paths["json"], "--rays-out", paths["rays"],
               "--hits-out", paths["hits"], "--allow-outside-paths", "-q"]
    run(command, "raylab bench")
    with open(paths["json"], encoding="utf-8") as f:
        report = json.load(f)
    return report, command, paths


def figure(report_set, way, side):
    """Mrays/s of `side` ("ours" or "embree") for `way` ("single" or "packet16"); None if not measured."""
    entry = report_set.get(way)
    return None if entry is None else entry["mrays_per_s"][side]


def read_rays(path):
    """The records of a .rays file as an (N, 8) float32 array."""
    return np.fromfile(path, dtype=RAY_DTYPE).reshape(-1, 8)


def ray_limits(records):
    """(tmin, tmax, description) for Scene.intersect: the one tmin and tmax all rays share as
    numbers, else the records' own columns (float32 views, one limit per ray)."""
    tmin, tmax = records[:, 3], records[:, 7]
    if len(records) == 0:
        return 0.0, float("inf"), "no rays"
    if np.all(tmin == tmin[0]) and np.all(tmax == tmax[0]):
        return float(tmin[0]), float(tmax[0]), f"tmin {float(tmin[0])} tmax {float(tmax[0])} for every ray"
    return tmin, tmax, (f"per-ray limits ({np.unique(tmin).size} distinct tmin in [{tmin.min()}, {tmin.max()}], "
                        f"{np.unique(tmax).size} distinct tmax in [{tmax.min()}, {tmax.max()}]) passed as arrays")


def agreement(hits, cpp_hits):
    """How the module's hits compare with raylab bench's: identical records, and what differs."""
    t = hits["t"]
    prim = hits["prim_id"].view(np.uint32)  # -1 (miss) reads as 0xFFFFFFFF, the .hits miss id
    same_prim = prim == cpp_hits["prim"]
    same_t = t.view(np.uint32) == cpp_hits["t"].view(np.uint32)  # bit for bit
    identical = int(np.count_nonzero(same_prim & same_t))
    both = same_prim & np.isfinite(t)
    rel = np.abs(t[both].astype(np.float64) - cpp_hits["t"][both]) / np.maximum(np.abs(cpp_hits["t"][both]), 1e-30)
    return {"rays": int(len(t)), "identical": identical, "different_prim": int(np.count_nonzero(~same_prim)),
            "different_t_same_prim": int(np.count_nonzero(same_prim & ~same_t)),
            "max_rel_t_difference": float(rel.max()) if rel.size else 0.0}


def median_seconds(call, repeats):
    """Median wall-clock seconds of `repeats` calls of `call` (its result dropped at once)."""
    seconds = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        seconds.append(time.perf_counter() - start)
    return statistics.median(seconds)


def mrays(count, seconds):
    """Millions of rays per second."""
    return count / seconds / 1e6 if seconds > 0 else 0.0


def ratio(a, b):
    """a / b, or None when either is missing."""
    return a / b if a is not None and b else None


def query_overhead(binary, scene, rays_path, threads, repeats):
    """raylab_query_overhead's figures on these rays (None when this build lacks it)."""
    tool = pathlib.Path(binary).with_name("raylab_query_overhead")
    if not os.access(tool, os.X_OK):
        return None, None
    command = [str(tool), scene, rays_path, "--threads", str(threads), "--repeats", str(max(repeats, 3)),
               "--allow-outside-paths"]
    return json.loads(run(command, "query overhead")), command


# glibc settings for a process that keeps the memory it frees: no block of up to 32 MiB (the
# most M_MMAP_THRESHOLD takes) is mapped on its own, and the heap's top is never trimmed.
KEEP_PAGES_ENV = {"MALLOC_MMAP_THRESHOLD_": str(32 << 20), "MALLOC_TRIM_THRESHOLD_": str(1 << 40)}


def python_pages_kept(scene_path, rays_path, threads, repeats):
    """Mrays/s of Scene.intersect (all answers, then t and prim_id) in a child process with KEEP_PAGES_ENV.

    Each call returns new numpy arrays of answers, 32 bytes a ray (8 with t and prim_id). When glibc hands the freed
    arrays of the previous call back to the kernel, every call faults its output pages in again
    and the kernel zeroes them; whether it does depends on the heap's layout. The child shows
    the speed without that cost (see --time-intersect).
    """
    command = [sys.executable, str(pathlib.Path(__file__).resolve()), "--time-intersect", scene_path, rays_path,
               str(threads), str(repeats)]
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, env={**os.environ, **KEEP_PAGES_ENV})
    if done.returncode != 0:
        raise SystemExit(f"bench_python: {shlex.join(command)} failed:\n{done.stderr}")
    figures = json.loads(done.stdout)
    return figures["mrays_per_s"], figures["mrays_per_s_hits"]


def time_intersect(scene_path, rays_path, threads, repeats):
    """The child of python_pages_kept: loads, builds, traces once, prints the median Mrays/s of
    all answers and of t and prim_id."""
    scene = raylab.load(scene_path, allow_outside_paths=True).build("bvh", threads=threads)
    records = read_rays(rays_path)
    tmin, tmax, _ = ray_limits(records)
    trace = functools.partial(scene.intersect, records[:, 0:3], records[:, 4:7], tmin=tmin, tmax=tmax,
                              threads=threads)
    trace_hits = functools.partial(trace, fields=list(HIT_FIELDS))
    trace()
    trace_hits()
    print(json.dumps({"mrays_per_s": mrays(len(records), median_seconds(trace, repeats)),
                      "mrays_per_s_hits": mrays(len(records), median_seconds(trace_hits, repeats))}))


def ray_sample(args, scene, kind, threads, loaded, out_dir):
    """One round of one row: raylab bench, the query split, then the module on the same rays,
    in this process and in one whose freed memory glibc keeps (`loaded`: path and Scene)."""
    py_path, py_scene = loaded
    report, command, paths = cpp_bench(args.binary, scene, kind, threads, args.repeats, args.width, args.height,
                                       out_dir)
    if py_scene.primitive_count != report["primitives"]:
        raise SystemExit(f"bench_python: {scene}: the module loaded {py_scene.primitive_count} primitives, "
                         f"raylab bench {report['primitives']}")
    cpp_set = report["sets"][0]
    sample = {"rays": cpp_set["rays"], "hit": cpp_set["answered"], "cpp_command": shlex.join(command),
              "cpp_single": figure(cpp_set, "single", "ours"), "cpp_packet16": figure(cpp_set, "packet16", "ours"),
              "embree_single": figure(cpp_set, "single", "embree"),
              "embree_packet16": figure(cpp_set, "packet16", "embree")}
    records = read_rays(paths["rays"])
    tmin, tmax, sample["limits"] = ray_limits(records)
    overhead, overhead_command = query_overhead(args.binary, scene, paths["rays"], threads, args.repeats)
    if overhead:
        sample["query"] = overhead["mrays_per_s"]
        sample["query_command"] = shlex.join(overhead_command)
    origins, directions = records[:, 0:3], records[:, 4:7]  # float32 views of the records, no copy
    trace = functools.partial(py_scene.intersect, origins, directions, tmin=tmin, tmax=tmax, threads=threads)
    trace_hits = functools.partial(trace, fields=list(HIT_FIELDS))
    cpp_hits = np.fromfile(paths["hits"], dtype=HIT_DTYPE)
    sample["agreement"] = agreement(trace(), cpp_hits)  # also the warm-ups
    hits = trace_hits()
    if sorted(hits) != sorted(HIT_FIELDS):
        raise SystemExit(f"bench_python: intersect(fields={list(HIT_FIELDS)}) answered {sorted(hits)}")
    sample["agreement_hits"] = agreement(hits, cpp_hits)
    # The two forms alternate, so that a change of the machine's load falls on both alike.
    seconds, seconds_hits = [], []
    for _ in range(args.repeats):
        seconds.append(median_seconds(trace, 1))
        seconds_hits.append(median_seconds(trace_hits, 1))
    sample["python"] = mrays(len(records), statistics.median(seconds))
    sample["python_hits"] = mrays(len(records), statistics.median(seconds_hits))
    sample["python_pages_kept"], sample["python_hits_pages_kept"] = python_pages_kept(
        py_path, paths["rays"], threads, args.repeats)
    return sample


def merged(samples, figures):
    """The rounds of one row as one: the median of each figure in `figures`, the rest from the first."""
    row = dict(samples[0])
    for key in figures:
        values = [s[key] for s in samples if s.get(key) is not None]
        row[key] = statistics.median(values) if values else None
    row["rounds"] = [{key: s.get(key) for key in figures} for s in samples]
    return row


def ray_figures(args, out_dir, notes):
    """One row per scene, thread count and ray kind: the C++ figures, the module's, their ratios."""
    scenes = {}
    for name, scene in RAY_SCENES:
        if name in args.scenes:
            # allow_outside_paths as raylab bench's --allow-outside-paths: the bench's bunny refers
            # to ../../../shared/scenes.
            scenes[name] = (str(ROOT / scene), raylab.load(ROOT / scene, allow_outside_paths=True))
    samples = {}
    for round_index in range(args.rounds):
        for name, scene in RAY_SCENES:
            if name not in scenes:
                continue
            for threads in args.threads:
                scenes[name][1].build("bvh", threads=threads)
                for kind in RAY_KINDS:
                    sample = ray_sample(args, scene, kind, threads, scenes[name], out_dir)
                    samples.setdefault((name, scene, threads, kind), []).append(sample)
                    log(f"round {round_index + 1}: {name} t{threads} {kind}: python all "
                        f"{fmt(sample['python'])}, t+prim_id {fmt(sample['python_hits'])} Mrays/s, "
                        f"C++ single {fmt(sample['cpp_single'])}, packet16 {fmt(sample['cpp_packet16'])}")
    limits = sorted({s["limits"] for group in samples.values() for s in group})
    notes.append("ray limits of the .rays records traced (checked ray by ray; numbers passed as Scene.intersect's "
                 "tmin and tmax, per-ray limits as arrays): " + "; ".join(limits))
    rows = []
    for (name, scene, threads, kind), group in samples.items():
        for s in group:
            for key, value in s.pop("query", {}).items():
                s["query_" + key] = value
        row = merged(group, ["cpp_single", "cpp_packet16", "embree_single", "embree_packet16", "python",
                             "python_hits", "python_pages_kept", "python_hits_pages_kept", "query_hits_only",
                             "query_all_outputs"])
        row.update(scene=name, file=scene, threads=threads, kind=kind)
        for key in ("agreement", "agreement_hits"):
            row[key] = min((s[key] for s in group), key=lambda a: a["identical"])
        row["cpp_path"] = max(f for f in (row["cpp_single"], row["cpp_packet16"]) if f is not None)
        for py in ("python", "python_hits"):
            prefix = "py" if py == "python" else "py_hits"
            row[f"{prefix}_vs_cpp_path"] = ratio(row[py], row["cpp_path"])
            row[f"{prefix}_vs_cpp_single"] = ratio(row[py], row["cpp_single"])
            row[f"{prefix}_vs_cpp_packet16"] = ratio(row[py], row["cpp_packet16"])
            row[f"{prefix}_vs_embree_single"] = ratio(row[py], row["embree_single"])
        rows.append(row)
    return rows


def read_obj(path):
    """(vertices float32 (N, 3), triangles uint32 (M, 3)) of an OBJ file of triangles."""
    vertices, faces = [], []
    with open(path, encoding="ascii", errors="replace") as f:
        for line in f:
            if line.startswith("v "):
                vertices.append(line.split()[1:4])
            elif line.startswith("f "):
                corners = [int(c.split("/")[0]) for c in line.split()[1:]]
                if len(corners) != 3:
                    raise ValueError(f"{path}: a face of {len(corners)} corners (only triangles are read here)")
                faces.append(corners)
    v = np.array(vertices, dtype=np.float64).astype(np.float32)
    f = np.array(faces, dtype=np.int64)
    f = np.where(f < 0, len(v) + f, f - 1)  # 1-based; negative indices count back from the last vertex
    return v, f.astype(np.uint32)


def read_ply_tristrips(path):
    """(vertices float32 (N, 3), triangles uint32 (M, 3)) of a binary little-endian PLY whose faces
    are one `tristrips` element of int lists (igea.ply), expanded as raylab's loader does."""
    scalar = {"char": "i1", "uchar": "u1", "short": "<i2", "ushort": "<u2", "int": "<i4", "uint": "<u4",
              "float": "<f4", "double": "<f8", "int32": "<i4", "uint32": "<u4", "float32": "<f4"}
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    elements = []
    for line in data[:end].decode("ascii").splitlines():
        words = line.split()
        if words[:1] == ["format"] and words[1] != "binary_little_endian":
            raise ValueError(f"{path}: only binary_little_endian PLY is read here")
        if words[:1] == ["element"]:
            elements.append((words[1], int(words[2]), []))
        elif words[:1] == ["property"]:
            elements[-1][2].append(words[1:])
    offset = end
    vertices = triangles = None
    for name, count, props in elements:
        if name == "vertex":
            dtype = np.dtype([(p[-1], scalar[p[0]]) for p in props])
            table = np.frombuffer(data, dtype=dtype, count=count, offset=offset)
            vertices = np.stack([table["x"], table["y"], table["z"]], axis=1).astype(np.float32)
            offset += dtype.itemsize * count
        elif name == "tristrips" and props == [["list", "int", "int", "vertex_indices"]]:
            strips = []
            for _ in range(count):
                n = int(np.frombuffer(data, dtype="<i4", count=1, offset=offset)[0])
                strips += [np.frombuffer(data, dtype="<i4", count=n, offset=offset + 4), np.array([-1], "<i4")]
                offset += 4 + 4 * n
            triangles = strip_triangles(np.concatenate(strips))
        else:
            raise ValueError(f"{path}: element {name} {props} is not read here")
    return vertices, drop_zero_area(vertices, triangles)


def strip_triangles(strip):
    """Triangles of a strip with -1 restarts: each vertex after a run's first two with the two
    before it, every other one with its first two corners swapped to keep the winding."""
    index = np.arange(len(strip))
    restart = strip == -1
    run_start = np.maximum.accumulate(np.where(restart, index, -1)) + 1
    position = index - run_start  # place in its run
    at = index[~restart & (position >= 2)]
    a, b, c = strip[at - 2], strip[at - 1], strip[at]
    even = (position[at] % 2 == 0)[:, None]
    return np.where(even, np.stack([a, b, c], axis=1), np.stack([b, a, c], axis=1)).astype(np.uint32)


def drop_zero_area(vertices, triangles):
    """The triangles whose float32 normal is not zero, as raylab's loaders keep them."""
    p0, p1, p2 = (vertices[triangles[:, k]] for k in range(3))
    e1, e2 = p1 - p0, p2 - p0
    n = np.stack([e1[:, 1] * e2[:, 2] - e1[:, 2] * e2[:, 1], e1[:, 2] * e2[:, 0] - e1[:, 0] * e2[:, 2],
                  e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0]], axis=1)
    return triangles[(n[:, 0] * n[:, 0] + n[:, 1] * n[:, 1] + n[:, 2] * n[:, 2]) > 0]


def same_mesh(mesh, loaded):
    """Whether a Mesh and the loaded file answer 64x48 camera rays identically (t and prim_id)."""
    lo, hi = loaded.bounds
    centre, size = (lo + hi) / 2, float(np.linalg.norm(hi - lo))
    rays = raylab.pinhole_rays(64, 48, eye=tuple(centre + np.array([0.3, 0.2, 1.0]) * size), at=tuple(centre), fov=40)
    a, b = mesh.intersect(rays), loaded.intersect(rays)
    return bool(np.array_equal(a["t"], b["t"]) and np.array_equal(a["prim_id"], b["prim_id"]))


def build_sample(args, mesh_file, threads, vertices, triangles, out_dir):
    """One round of one build row: raylab bench's build (a few rays only), then Mesh(...).build."""
    report, command, _ = cpp_bench(args.binary, mesh_file, "primary", threads, args.repeats, 64, 48, out_dir,
                                   purpose="build")
    make_s, build_s, total_s = [], [], []
    for _ in range(args.repeats):
        start = time.perf_counter()
        scene = raylab.Mesh(vertices, triangles)
        made = time.perf_counter()
        scene.build("bvh", threads=threads)
        built = time.perf_counter()
        make_s.append(made - start)
        build_s.append(built - made)
        total_s.append(built - start)
        del scene  # freed before the next build, as raylab bench frees its previous one
    return {"cpp_command": shlex.join(command), "cpp_build_ms": report["build_ms"]["ours"],
            "embree_build_ms": report["build_ms"]["embree"], "py_mesh_ms": statistics.median(make_s) * 1e3,
            "py_build_ms": statistics.median(build_s) * 1e3, "py_total_ms": statistics.median(total_s) * 1e3}


def build_figures(args, out_dir):
    """One row per mesh and thread count: raylab bench's build time against Mesh(...).build("bvh")."""
    meshes = {}
    for name, mesh_file in BUILD_MESHES:
        if name not in args.scenes:
            continue
        path = ROOT / mesh_file
        start = time.perf_counter()
        vertices, triangles = read_obj(path) if path.suffix == ".obj" else read_ply_tristrips(path)
        parse_ms = (time.perf_counter() - start) * 1e3
        loaded, mesh = raylab.load(path), raylab.Mesh(vertices, triangles)
        if mesh.primitive_count != loaded.primitive_count or not same_mesh(mesh, loaded):
            raise SystemExit(f"bench_python: {mesh_file}: the numpy arrays ({mesh.primitive_count} triangles) "
                             f"are not the loader's mesh ({loaded.primitive_count} primitives)")
        meshes[name] = (mesh_file, vertices, triangles, parse_ms)
    samples = {}
    for _ in range(args.rounds):
        for name, (mesh_file, vertices, triangles, _) in meshes.items():
            for threads in args.threads:
                sample = build_sample(args, mesh_file, threads, vertices, triangles, out_dir)
                samples.setdefault((name, threads), []).append(sample)
                log(f"build {name} t{threads}: python {sample['py_total_ms']:.1f} ms, "
                    f"C++ {sample['cpp_build_ms']:.1f} ms")
    rows = []
    for (name, threads), group in samples.items():
        mesh_file, vertices, triangles, parse_ms = meshes[name]
        row = merged(group, ["cpp_build_ms", "embree_build_ms", "py_mesh_ms", "py_build_ms", "py_total_ms"])
        row.update(mesh=name, file=mesh_file, threads=threads, triangles=int(len(triangles)), parse_ms=parse_ms)
        row["py_vs_cpp_build"] = ratio(row["py_total_ms"], row["cpp_build_ms"])
        rows.append(row)
    return rows


def fmt(value, digits=2):
    """A figure for the table; '-' when not measured."""
    return "-" if value is None else f"{value:.{digits}f}"


def machine():
    """The processor, core count and vector extensions, as /proc/cpuinfo says."""
    model, flags = platform.processor() or "unknown", set()
    try:
        with open("/proc/cpuinfo", encoding="ascii", errors="replace") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                elif line.startswith("flags"):
                    flags = set(line.split(":", 1)[1].split())
    except OSError:
        pass
    isa = "AVX-512" if "avx512f" in flags else "AVX2" if "avx2" in flags else "no AVX2"
    return f"{model}, {os.cpu_count()} cores, {isa}"


def commit():
    """The project's commit (short hash), with '+' when the tree has changes; None outside git."""
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True,
                              check=True).stdout.strip()
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=ROOT, capture_output=True,
                               text=True, check=True).stdout.strip()
        return head + ("+" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return None


def tables(result):
    """The report as markdown tables, then the bars."""
    out = [f"raylab {raylab.__version__} at commit {result['commit']}; {result['machine']}; {result['date']}; "
           f"median of {result['repeats']} runs in each of {result['rounds']} rounds, median over the rounds; "
           f"load average {result['load_before']:.2f} before, "
           f"{result['load_after']:.2f} after", ""]
    out += ["Closest hits on the rays of `raylab bench` (Mrays/s). C++ path = the faster of our single and "
            "packet16, the path Scene.intersect takes. Python all = `scene.intersect(origins, directions)`, all five "
            "answers (the default); Python t+prim_id = the same with `fields=[\"t\", \"prim_id\"]`, the two answers "
            "raylab bench writes. Each ratio is given for both, as all / t+prim_id", "",
            "| scene | threads | rays | C++ single | C++ packet16 | Embree single | Embree packet16 | Python all "
            "| Python t+prim_id | Py / C++ path | Py / C++ single | Py / Embree single | agreement |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]

    def pair(r, key):
        """The ratio `key` of the all-answers figure and of the t+prim_id one, as 'a / b'."""
        return f"{fmt(r['py_' + key], 3)} / {fmt(r['py_hits_' + key], 3)}"

    for r in result["rays"]:
        same = []
        for label, a in (("all", r["agreement"]), ("t+prim_id", r["agreement_hits"])):
            same.append(f"{label}: {a['identical']}/{a['rays']} identical" if a["identical"] == a["rays"] else (
                f"{label}: {a['identical']}/{a['rays']} identical, {a['different_prim']} other prim, max rel t "
                f"{a['max_rel_t_difference']:.1e}"))
        out.append(f"| {r['scene']} | {r['threads']} | {r['kind']} {r['rays']} | {fmt(r['cpp_single'])} "
                   f"| {fmt(r['cpp_packet16'])} | {fmt(r['embree_single'])} | {fmt(r['embree_packet16'])} "
                   f"| {fmt(r['python'])} | {fmt(r['python_hits'])} | {pair(r, 'vs_cpp_path')} "
                   f"| {pair(r, 'vs_cpp_single')} | {pair(r, 'vs_embree_single')} | {'; '.join(same)} |")
    split = [r for r in result["rays"] if "python" in r]
    if split:
        out += ["", "Where the time goes (Mrays/s): the C++ path of raylab bench; RayQuery::intersect in C++ "
                "(raylab_query_overhead: the call behind Scene.intersect) writing t and prim_id only, then all five "
                "answers; the module asked for t and prim_id, then for all five, each in a process whose freed "
                "memory glibc keeps (kept) and as run above", "",
                "| scene | threads | rays | C++ path | query, t+prim_id | Python t+prim_id, kept | Python t+prim_id "
                "| query, all | Python all, kept | Python all | query t+prim_id / path | Py t+prim_id / query "
                "| query all / query t+prim_id | Py all / query all |",
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in split:
            hits, every = r.get("query_hits_only"), r.get("query_all_outputs")
            out.append(f"| {r['scene']} | {r['threads']} | {r['kind']} | {fmt(r['cpp_path'])} | {fmt(hits)} "
                       f"| {fmt(r['python_hits_pages_kept'])} | {fmt(r['python_hits'])} | {fmt(every)} "
                       f"| {fmt(r['python_pages_kept'])} | {fmt(r['python'])} | {fmt(ratio(hits, r['cpp_path']), 3)} "
                       f"| {fmt(ratio(r['python_hits'], hits), 3)} | {fmt(ratio(every, hits), 3)} "
                       f"| {fmt(ratio(r['python'], every), 3)} |")
    if result["build"]:
        out += ["", "Build from numpy arrays: `raylab.Mesh(vertices, triangles).build(\"bvh\")` against raylab bench's "
                "build of the same file (ms)", "",
                "| mesh | threads | triangles | C++ build | Embree build | Mesh() | build() | Python total "
                "| Py total / C++ |", "|---|---|---|---|---|---|---|---|---|"]
        for r in result["build"]:
            out.append(f"| {r['mesh']} | {r['threads']} | {r['triangles']} | {fmt(r['cpp_build_ms'], 1)} "
                       f"| {fmt(r['embree_build_ms'], 1)} | {fmt(r['py_mesh_ms'], 1)} | {fmt(r['py_build_ms'], 1)} "
                       f"| {fmt(r['py_total_ms'], 1)} | {fmt(r['py_vs_cpp_build'], 3)} |")
    out += [""] + [f"bar: {line}" for line in bars(result)]
    out += [f"note: {n}" for n in result["notes"]]
    out += ["", "commands:"] + sorted({r["cpp_command"] for r in result["rays"] + result["build"]})
    out += sorted({r["query_command"] for r in result["rays"] if "query_command" in r})
    return "\n".join(out)


def bars(result):
    """One line per bar of the issue: met or not, and the rows that miss it."""

    def verdict(label, rows, value, ok):
        misses = [f"{key} {value(r):.3f}" for key, r in rows if not ok(value(r))]
        met = len(rows) - len(misses)
        return f"{label}: met on {met} of {len(rows)}" + (f"; missed: {', '.join(misses)}" if misses else "")

    traced = [(f"{r['scene']} t{r['threads']} {r['kind']}", r) for r in result["rays"] if "python" in r]
    primary = [(k, r) for k, r in traced if r["kind"] == "primary" and r["embree_single"]]
    built = [(f"{r['mesh']} t{r['threads']}", r) for r in result["build"]]
    lines = []
    for prefix, label in (("py", "Python all answers"), ("py_hits", "Python t+prim_id")):
        lines += [verdict(f"{label} >= {BAR_VS_CPP}x raylab C++ (C++ path)", traced,
                          lambda r, p=prefix: r[f"{p}_vs_cpp_path"], lambda v: v >= BAR_VS_CPP),
                  verdict(f"primary rays: {label} >= {BAR_VS_EMBREE_PRIMARY}x Embree rtcIntersect1", primary,
                          lambda r, p=prefix: r[f"{p}_vs_embree_single"], lambda v: v >= BAR_VS_EMBREE_PRIMARY)]
    return lines + [verdict(f"build from numpy <= {BAR_BUILD}x C++ build", built, lambda r: r["py_vs_cpp_build"],
                            lambda v: v <= BAR_BUILD)]


def main():
    """Runs every figure and prints the tables (and writes the JSON)."""
    if sys.argv[1:2] == ["--time-intersect"]:  # the child of python_pages_kept
        scene_path, rays_path, threads, repeats = sys.argv[2:6]
        return time_intersect(scene_path, rays_path, int(threads), int(repeats))
    args = parse_args()
    started = time.perf_counter()
    result = {"machine": machine(), "commit": commit(), "date": datetime.date.today().isoformat(),
              "repeats": args.repeats, "rounds": args.rounds, "threads": args.threads, "width": args.width, "height": args.height,
              "load_before": os.getloadavg()[0], "notes": []}
    with tempfile.TemporaryDirectory(prefix="bench_python.") as temp:
        out_dir = pathlib.Path(args.workdir or temp)
        out_dir.mkdir(parents=True, exist_ok=True)
        result["rays"] = ray_figures(args, out_dir, result["notes"])
        result["build"] = build_figures(args, out_dir)
    result["load_after"] = os.getloadavg()[0]
    result["bars"] = bars(result)
    result["seconds"] = time.perf_counter() - started
    print(tables(result))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as f:
            json.dump(result, f, indent=2)
            f.write("\n")
    log(f"done in {result['seconds']:.0f} s")


if __name__ == "__main__":
    main()
