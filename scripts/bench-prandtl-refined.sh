#!/usr/bin/env bash
# The Prandtl footing, flexible (examples/prandtl-flexible-footing.json) or rigid on its smooth
# interface (examples/prandtl-footing.json, with the flexible one's global mesh size of 4 m), on
# the load sequence of Smith & Griffiths' program 6.1 (as scripts/bench-prandtl.sh), on 48 meshes
# refined at the footing's edge, where the stress is singular: a size along the footing (0.4,
# 0.6, 0.8 m), a point refinement at its edge (2 cm to 5 cm within 5 or 10 cm) and two gradings. Each mesh runs
# with the last increment halved down to 1/64 (the default) and with whole steps
# (min_load_fraction 1), one thread. Prints one row per run and then, per floor, the range of the
# error of the load carried against 2 + π, the runs that "collapsed" below 90 % of it, the meshes
# whose two brackets do not overlap, the factorisations and the CPU time of all runs
# (docs/benchmarks.md, "Newton minimising the energy under a load").
#
#   bash scripts/bench-prandtl-refined.sh [flexible|rigid] [MCDDA_BINARY] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
footing=${1:-flexible}
mcdda=${2:-build/app/mcdda}
out=${3:-out/bench-prandtl-refined-$footing}
case "$footing" in
  flexible) model=examples/prandtl-flexible-footing.json; along_radius=0.3 ;;
  rigid) model=examples/prandtl-footing.json; along_radius=0.5 ;;
  *) echo "usage: bash scripts/bench-prandtl-refined.sh [flexible|rigid] [MCDDA_BINARY] [OUT_DIR]" >&2; exit 2 ;;
esac
[ -x "$mcdda" ] || bash scripts/build.sh
mkdir -p "$out"
rows="$out/rows.txt"
: > "$rows"

for along in 0.4 0.6 0.8; do
  for edge in 0.02 0.03 0.04 0.05; do
    for radius in 0.05 0.1; do
      for grading in 0.3 0.5; do
        for floor in 1 0.015625; do
          name="L$along-p$edge-r$radius-g$grading-f$floor"
          rm -rf "$out/$name"
          /usr/bin/time -f '%U %S' -o "$out/$name.time" "$mcdda" run "$model" \
            --out "$out/$name" --quiet --threads 1 --set /mesh/size=4 \
            --set /edge_pressures/0/pressure=1000 --set /analysis/steps=80 --set /analysis/output_every=1000 \
            --set '/load_tables/0/points=[[0,0],[1,200],[2,300],[3,350],[4,400],[5,450],[6,480],[7,481]]' \
            --set /analysis/min_load_fraction=$floor --set /mesh/grading=$grading \
            --set "/mesh/local=[{\"from\": [0, 0], \"to\": [2, 0], \"size\": $along, \"radius\": $along_radius},
                               {\"point\": [2, 0], \"size\": $edge, \"radius\": $radius}]" >/dev/null 2>&1 || true
          python3 - "$out/$name" "$name" "$(tail -1 "$out/$name.time")" >> "$rows" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
c = s.get("collapse") or {}
carried = c.get("carried", {}).get("loads", {}).get("footing load")
q = carried / 100e3 if carried is not None else float("nan")
cpu = sum(float(x) for x in sys.argv[3].split())
fact = s["timing"].get("factorizations", s.get("factorizations", 0))
print("%-32s %5d %10.5f %+8.3f %5d %6.2f" % (sys.argv[2], s["model"]["elements"], q, 100 * (q / (2 + math.pi) - 1), fact, cpu))
PY
        done
      done
    done
  done
done

printf '%-32s %5s %10s %8s %5s %6s\n' run elements "q/cu" "error %" fact "CPU s"
cat "$rows"
python3 - "$rows" <<'PY'
import sys, collections
runs = {}
for line in open(sys.argv[1]):
    name, elements, q, err, fact, cpu = line.split()
    mesh, floor = name.rsplit("-f", 1)
    runs[(mesh, floor)] = (float(q), float(err), int(fact), float(cpu))
for floor, label in (("0.015625", "halved to 1/64"), ("1", "whole steps")):
    rows = [v for (m, f), v in runs.items() if f == floor]
    errors = [r[1] for r in rows]
    false = sum(1 for r in rows if not r[0] > 0.9 * 5.1416)
    print("%-15s runs %d, error %+.3f to %+.3f %%, collapsed below 90 %%: %d, factorisations %d, CPU %.1f s"
          % (label, len(rows), min(errors), max(errors), false, sum(r[2] for r in rows), sum(r[3] for r in rows)))
apart = [m for (m, f) in runs if f == "1" and not (runs[(m, "1")][0] - 1e-9 <= runs[(m, "0.015625")][0]
                                                   < runs[(m, "1")][0] + 0.01 + 1e-9)]
print("meshes whose brackets do not overlap: %d %s" % (len(apart), " ".join(sorted(apart))))
PY
