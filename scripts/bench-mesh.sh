#!/usr/bin/env bash
# Meshing benchmark: the jointed tunnel refined to well over 100,000 triangles, with a timing
# breakdown (read, validate, cut, mesh, write). Rerun after changes to the cutter or mesher.
# Usage: bash scripts/bench-mesh.sh [SIZE]   (global element size in m, default 0.15)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-0.15}
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
mkdir -p out/bench
"$mcdda" mesh examples/jointed-tunnel.json --out out/bench --set /mesh/size="$size" --profile
