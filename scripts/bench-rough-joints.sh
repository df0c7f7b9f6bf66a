#!/bin/bash
# Rough joints below the toe of a stable slope: examples/slope-wedge.json with its joints' friction
# raised to 45° (the wedge stands) and one more joint about y = −2 or −3 m, ±4 cm: random
# zigzags of 300, 1,000 and 3,000 vertices (three seeds each) and regular sawtooths of 300 and
# 1,000 vertices, crossing the model's sides or, "flat", ending in straight stretches 1.5 m long.
# One step each, one thread: the outcome, the unbalanced-force ratio and the CPU time of the
# process (docs/benchmarks.md, "Rules for vertices at a rough joint's corners").
#
#   scripts/bench-rough-joints.sh [MCDDA_BINARY] [OUT_DIR]
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/app/mcdda}
out=${2:-$(mktemp -d)}
mkdir -p "$out/models"
python3 - "$here/examples/slope-wedge.json" "$out/models" <<'PY'
import json, random, sys
base = json.load(open(sys.argv[1]))
base["joint_materials"][0]["friction_angle"] = 45
def write(name, points):
    model = json.loads(json.dumps(base))
    model["joints"].append({"name": "rough joint", "points": points})
    model["analysis"]["steps"] = 1
    json.dump(model, open(f"{sys.argv[2]}/{name}.json", "w"))
for n in (300, 1000, 3000):
    for seed in (1, 2, 3):
        draw = random.Random(seed)
        write(f"random{n}-seed{seed}", [[-1.0 + 42.0 * k / (n - 1), -2.0 + draw.uniform(-0.04, 0.04)] for k in range(n)])
for n in (300, 1000):
    for y in (-2.0, -3.0):
        tooth = lambda k: y + (0.04 if k % 2 else -0.04)
        write(f"sawtooth{n}-y{-y:.0f}", [[-1.0 + 42.0 * k / (n - 1), tooth(k)] for k in range(n)])
        write(f"sawtooth{n}-y{-y:.0f}-flat-ends",
              [[-1.0, y]] + [[0.5 + 39.0 * k / (n - 1), tooth(k)] for k in range(n)] + [[41.0, y]])
PY
printf '%-26s %-11s %10s %8s\n' model status ratio "CPU (s)"
for model in "$out"/models/*.json; do
    name=$(basename "$model" .json)
    /usr/bin/time -f "%U" -o "$out/$name.time" "$bin" run "$model" --out "$out/$name" --quiet --threads 1 >/dev/null 2>&1 || true
    cpu=$(tail -1 "$out/$name.time")  # (after a line on a non-zero exit status)
    python3 - "$name" "$cpu" "$out/$name/summary.json" <<'PY'
import json, sys
name, cpu, path = sys.argv[1:4]
try:
    summary = json.load(open(path))
    status, ratio = summary["status"], f"{summary['unbalanced_ratio']:.3g}"
except (OSError, KeyError, ValueError):
    status, ratio = "no summary", "-"
print(f"{name:26s} {status:11s} {ratio:>10s} {cpu:>8s}")
PY
done
