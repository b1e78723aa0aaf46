#!/usr/bin/env bash
# Our kernels of each instruction set against Embree on the same rays: `raylab bench --isa SET`
# for every set this CPU runs, ROUNDS rounds alternating the sets, and per figure the median of
# ours / Embree over the rounds (each process times Embree beside us, which cancels the machine's
# moods between processes). Usage: scripts/isa-bench.sh SCENE [THREADS] [ROUNDS] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1
threads=${2:-1}
rounds=${3:-3}
build=${4:-build/release}
raylab="$build/bin/raylab"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

sets=$(/usr/bin/python3 -c "import re,sys; print(' '.join(re.search(r'this CPU: ([^)]*)', sys.argv[1]).group(1).split(', ')))" \
  "$("$raylab" --version)")
echo "# $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); sets: $sets"
echo "# raylab bench $scene --threads $threads --repeats 5 --allow-outside-paths --isa SET, $rounds rounds"
for round in $(seq "$rounds"); do
  for set in $sets; do
    # Progress goes to a log, shown only when a run fails.
    "$raylab" bench "$scene" --threads "$threads" --repeats 5 --allow-outside-paths --isa "$set" \
      --json "$out/$set-$round.json" >/dev/null 2>"$out/log" || { cat "$out/log" >&2; exit 1; }
  done
done
/usr/bin/python3 - "$out" $sets <<'PY'
import glob, json, statistics, sys
out, sets = sys.argv[1], sys.argv[2:]
figures = {}
for s in sets:
    for path in sorted(glob.glob(f"{out}/{s}-*.json")):
        doc = json.load(open(path))
        rows = [("build Mprims/s", doc["build_mprims_per_s"])]
        for st in doc["sets"]:
            rows.append((st["name"] + " single", st["single"]["mrays_per_s"]))
            if st["packet16"]:
                rows.append((st["name"] + " packet16", st["packet16"]["mrays_per_s"]))
        for name, f in rows:
            figures.setdefault(name, {}).setdefault(s, []).append((f["ours"], f["ratio"]))
print("| figure | " + " | ".join(f"{s} Mrays/s, ours/Embree" for s in sets) + " |")
print("|---" * (len(sets) + 1) + "|")
for name, by_set in figures.items():
    cells = []
    for s in sets:
        ours = statistics.median(o for o, _ in by_set[s])
        ratio = statistics.median(r for _, r in by_set[s])
        cells.append(f"{ours:.2f}, {ratio:.2f}")
    print(f"| {name} | " + " | ".join(cells) + " |")
PY
