#!/usr/bin/env bash
# Plasticity benchmark: the Prandtl footing on the load sequence of Smith & Griffiths'
# program 6.1 — 200, 300, 350, 400, 450, 480 kPa, then +1 kPa per step until collapse — with
# three- and six-node elements on several meshes (each example's own, refined at the footing's
# edge, and uniform sizes along the footing), for the flexible footing (a pressure on the
# soil, as the reference program loads it: examples/prandtl-flexible-footing.json) and the rigid
# one (a footing block on a smooth interface: examples/prandtl-footing.json). Each case runs with
# the last increment bisected to 1/64 (the default) and without bisection (min_load_fraction 1,
# the reference's 1 kPa resolution). Prints, per case, the collapse bracket as q/cu, the error of
# the load carried against 2 + π and the CPU time of the whole process (user + sys), and
# side by side the reference program's figures as measured on this kind of machine.
# Usage: bash scripts/bench-prandtl.sh [quick]   (quick: the flexible footing only)
#        OLD=path/to/other/mcdda bash scripts/bench-prandtl.sh   runs every case with that build too,
#        in the same session, one row each ("build" column), for a side-by-side CPU comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
mkdir -p out

sequence=(--set /edge_pressures/0/pressure=1000 --set /analysis/steps=80 --set /analysis/output_every=1000
          --set '/load_tables/0/points=[[0,0],[1,200],[2,300],[3,350],[4,400],[5,450],[6,480],[7,481]]')

# case: footing element local_size global_size floor; with OLD set, once per build
run_case() {
  run_with "$mcdda" this "$@"
  [ -z "${OLD:-}" ] || run_with "$OLD" old "$@"
}

run_with() {
  local binary=$1 build=$2 footing=$3 element=$4 size=$5 global=$6 floor=$7
  local model=examples/prandtl-footing.json radius=0.5 grading=0.25
  [ "$footing" = flexible ] && model=examples/prandtl-flexible-footing.json radius=0.3 grading=0.3
  local out="out/bench-prandtl-$build-$footing-$element-$size-$floor"
  # "shipped": the example's own mesh (refined at the footing's edge); a number: a uniform size
  # along the footing with the refinement radius and grading the examples had before (and the
  # rigid footing's block following the clay's size field, as it did).
  local mesh=()
  [ "$size" = shipped ] || mesh=(--set "/mesh/local=[{\"from\": [0, 0], \"to\": [2, 0], \"size\": $size, \"radius\": $radius}]"
                                 --set /mesh/grading="$grading" --set /mesh/size="$global")
  [ "$size" = shipped ] || [ "$footing" = flexible ] || mesh+=(--set /regions/1/mesh_size=0)
  rm -rf "$out"
  /usr/bin/time -f '%U %S' -o "$out.time" "$binary" run "$model" --out "$out" --quiet "${sequence[@]}" \
    --set /mesh/element="\"$element\"" "${mesh[@]}" \
    --set /analysis/min_load_fraction="$floor" >/dev/null 2>&1 || true
  local cpu
  cpu=$(tail -1 "$out.time" | awk '{print $1 + $2}')
  python3 - "$out/summary.json" "$footing" "$element" "$size" "$floor" "$cpu" "$build" <<'PY'
import json, math, sys
try:
    s = json.load(open(sys.argv[1]))
except (OSError, ValueError):
    print("%-5s %-9s %-4s %-7s %-5s  no summary.json (the run did not start)" % (sys.argv[7], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5]))
    sys.exit(0)
c = s.get("collapse") or {}
exact = 2 + math.pi
q = lambda v: v / 100e3  # footing pressure (Pa) → q/cu
carried = c.get("carried", {}).get("loads", {}).get("footing load")
failed = c.get("not_carried", {}).get("loads", {}).get("footing load")
text = "no collapse (%s)" % s.get("status") if carried is None else "%.4f – %.4f" % (q(carried), q(failed))
error = "" if carried is None else "%+.2f %%" % (100 * (q(carried) / exact - 1))
floor = "1/64" if abs(float(sys.argv[5]) - 1 / 64) < 1e-12 else sys.argv[5]
print("%-5s %-9s %-4s %-7s %-5s %9d %20s %8s %10d %8s" % (sys.argv[7], sys.argv[2], sys.argv[3], sys.argv[4], floor,
      s["model"]["elements"], text, error, s.get("factorizations", 0) or s["timing"].get("factorizations", 0), sys.argv[6]))
PY
}

printf '%-5s %-9s %-4s %-7s %-5s %9s %20s %8s %10s %8s\n' build footing elem local floor elements "collapse q/cu" error factorise "CPU (s)"
for size in shipped 0.5 0.4 0.3 0.2 0.1; do
  for floor in 0.015625 1; do run_case flexible t6 "$size" 4 "$floor"; done
done
for size in 0.4 0.1; do run_case flexible t3 "$size" 4 0.015625; done
if [ "${1:-}" != quick ]; then
  for size in shipped 0.4 0.2 0.1; do
    for floor in 0.015625 1; do run_case rigid t6 "$size" 1 "$floor"; done
  done
fi
echo "reference (Smith & Griffiths program 6.1, flexible footing, 32 eight-node quadrilaterals): 5.15 (+0.16 %) in 0.22 s CPU;"
echo "          2,048 quadrilaterals: 5.12 in 43 s (measured on this kind of machine)"
