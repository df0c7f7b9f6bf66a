#!/usr/bin/env bash
# Solver benchmark: a jointed rock mass (40 m square, two orthogonal joint sets at 4 m: 121
# blocks, about 1,750 contacts) under gravity, in-situ stress and overburden, meshed at two sizes,
# 40 static steps each (strong granite, the overburden raised by 40 % over the 40 steps: a
# constant one, as in the figures of docs/benchmarks.md before "Held factors solved in single
# precision", leaves nothing to solve after the first step since static steps at rest are
# skipped). Prints mcdda run --profile: time per step, factorisations, and the ratio of a step's
# time to one CHOLMOD factorisation.
# Usage: bash scripts/bench-run.sh [SIZES...]   (element sizes in m; default "1.3 0.39": ~5k and ~51k elements)
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(1.3 0.39)
for size in "${sizes[@]}"; do
  echo "== element size $size m"
  "$mcdda" run examples/jointed-tunnel.json --out "out/bench-run-$size" --quiet --profile \
    --set /regions/0/holes=[] --set /joints=[] \
    --set /joint_sets/0/angle=0 --set /joint_sets/1/angle=90 \
    --set /joint_sets/0/spacing=4 --set /joint_sets/1/spacing=4 \
    --set /joint_sets/0/origin=[0.5,0.5] --set /joint_sets/1/origin=[0.5,0.5] \
    --set /mesh/size="$size" --set /mesh/local=[] --set /measurement_points=[] \
    --set /analysis/steps=40 --set /analysis/output_every=1000 \
    --set /materials/0/cohesion=5e6 --set /materials/0/friction_angle=40 \
    --set /materials/0/tensile_strength=1e6 --set '/load_tables/0/points=[[0,1],[40,1.4]]'
  python3 -c "import json,sys; s=json.load(open('out/bench-run-$size/summary.json')); print('elements', s['model']['elements'], 'blocks', s['model']['blocks'])" 2>/dev/null || true
done
