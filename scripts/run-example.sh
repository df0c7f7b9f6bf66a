#!/usr/bin/env bash
# Quick start (a): builds mcdda and runs the main job on the default example.
#  - with a display: opens the desktop program with examples/jointed-tunnel.json;
#  - without one: checks, meshes, renders and runs that example headless into
#    out/jointed-tunnel/ (the mesh as .vtu, a PNG of the model, the analysis in results/ and a
#    PNG of its last step coloured by plastic state).
# Usage: bash scripts/run-example.sh [MODEL.json]
set -euo pipefail
cd "$(dirname "$0")/.."

model=${1:-examples/jointed-tunnel.json}
bash scripts/build.sh
name=$(basename "$model" .json)
out=out/$name

if [ -n "${DISPLAY:-}" ] && [ -z "${CI:-}" ]; then
  echo "Opening $model in the desktop program"
  exec build/app/gui/mcdda-gui "$model"
fi

echo "No display: running $model headless into $out/"
mkdir -p "$out"
build/app/mcdda check "$model"
build/app/mcdda mesh "$model" --out "$out"
build/app/mcdda render "$model" --out "$out/$name.png"
build/app/mcdda run "$model" --out "$out/results"
# The last saved step coloured by plastic state (grey elastic, yellow yielded, red yielding).
last=$(ls "$out"/results/*.vtu | tail -1)
build/app/mcdda render "$model" --results "$last" --field plastic_state --out "$out/$name-plastic-state.png"
echo "Results in $out: $(ls "$out" | tr '\n' ' '); analysis: $(ls "$out/results" | wc -l) files in $out/results"
