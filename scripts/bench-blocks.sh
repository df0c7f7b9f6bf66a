#!/usr/bin/env bash
# Ten thousand blocks: the rock mass of scripts/bench-run.sh with both joint sets at 0.4 m
# (10,201 blocks, 68,732 six-node elements, about 240,000 contacts) under
# gravity, in-situ stress and a constant overburden. Prints mcdda run --profile: time per step,
# factorisations, CPU time of the process.
# Usage: bash scripts/bench-blocks.sh [STEPS] [mcdda run options...]   (default 20 steps)
#   MCDDA=path/to/mcdda to use another build; e.g. two builds side by side, one thread each:
#   MCDDA=old/mcdda bash scripts/bench-blocks.sh 20 --threads 1 & bash scripts/bench-blocks.sh 20 --threads 1
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}
[ -x "$mcdda" ] || bash scripts/build.sh
steps=${1:-20}
shift $(( $# > 0 ? 1 : 0 ))
out=$(mktemp -d "${TMPDIR:-/tmp}/bench-blocks.XXXXXX")
trap 'rm -rf "$out"' EXIT
"$mcdda" run examples/jointed-tunnel.json --out "$out/run" --quiet --profile \
  --set /regions/0/holes=[] --set /joints=[] \
  --set /joint_sets/0/angle=0 --set /joint_sets/1/angle=90 \
  --set /joint_sets/0/spacing=0.4 --set /joint_sets/1/spacing=0.4 \
  --set /joint_sets/0/origin=[0.05,0.05] --set /joint_sets/1/origin=[0.05,0.05] \
  --set /mesh/size=0.4 --set /mesh/local=[] --set /measurement_points=[] \
  --set /analysis/steps="$steps" --set /analysis/output_every=1000 \
  --set /materials/0/cohesion=5e6 --set /materials/0/friction_angle=40 \
  --set /materials/0/tensile_strength=1e6 --set '/load_tables/0/points=[[0,1],[1,1]]' "$@"
python3 -c "
import json, sys
s = json.load(open(sys.argv[1]))
print('blocks', s['model']['blocks'], 'elements', s['model']['elements'], 'status', s['status'])
" "$out/run/summary.json"
