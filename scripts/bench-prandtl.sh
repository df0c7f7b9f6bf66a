#!/usr/bin/env bash
# Plasticity benchmark (issue 9): the Prandtl footing (examples/prandtl-footing.json) on the load
# sequence of Smith & Griffiths' program 6.1 — 200, 300, 350, 400, 450, 480 kPa, then +1 kPa per
# step until collapse — with three- and six-node elements on several meshes. Prints, per case, the
# collapse bracket as q/cu, its error against 2 + π and the CPU time of the process (user + sys).
# Usage: bash scripts/bench-prandtl.sh [LOCAL_SIZES...]   (refinement at the footing, m; default 0.4 0.2 0.1)
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(0.4 0.2 0.1)
printf '%-8s %-6s %9s %24s %8s %9s\n' element local elements "collapse q/cu" error "CPU (s)"
for element in t3 t6; do
  for size in "${sizes[@]}"; do
    out="out/bench-prandtl-$element-$size"
    rm -rf "$out"
    mkdir -p out
    /usr/bin/time -f '%U %S' -o "$out.time" "$mcdda" run examples/prandtl-footing.json --out "$out" --quiet \
      --set /mesh/element="\"$element\"" --set /mesh/local/0/size="$size" \
      --set /edge_pressures/0/pressure=1000 --set /analysis/steps=80 --set /analysis/output_every=1000 \
      --set '/load_tables/0/points=[[0,0],[1,200],[2,300],[3,350],[4,400],[5,450],[6,480],[7,481]]' \
      >/dev/null 2>&1 || true
    cpu=$(tail -1 "$out.time" | awk '{print $1 + $2}')
    python3 - "$out/summary.json" "$element" "$size" "$cpu" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
c = s.get("collapse") or {}
exact = 2 + math.pi
def q(v):  # footing pressure (Pa) at a load position → q/cu
    return v / 100e3
carried = c.get("carried", {}).get("loads", {}).get("footing load")
failed = c.get("not_carried", {}).get("loads", {}).get("footing load")
text = "no collapse (%s)" % s.get("status") if carried is None else "%.4f – %.4f" % (q(carried), q(failed))
error = "" if carried is None else "%+.2f %%" % (100 * (q(carried) / exact - 1))
print("%-8s %-6s %9d %24s %8s %9s" % (sys.argv[2], sys.argv[3], s["model"]["elements"], text, error, sys.argv[4]))
PY
  done
done
