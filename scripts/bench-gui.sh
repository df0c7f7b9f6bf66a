#!/usr/bin/env bash
# Desktop overhead benchmark: the same run headless (`mcdda run`) and in the desktop program
# with its live view (`mcdda-gui --run --quit-after-run`, under a virtual X server when there is
# no display), side by side, REPEAT times each, alternating. Prints the solver's own time
# (summary.json timing.total), wall and CPU time of each, and the desktop/headless ratios.
# Models: the Kirsch plate at about 104k elements (elastic, 20 steps) and Salençon's tunnel at
# 53k six-node elements (plastic, 20 steps).
# Usage: bash scripts/bench-gui.sh [REPEAT]   (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
repeat=${1:-2}
mcdda=${MCDDA:-build/app/mcdda}
gui=${MCDDA_GUI:-build/app/gui/mcdda-gui}
[ -x "$mcdda" ] && [ -x "$gui" ] || bash scripts/build.sh
dir=out/bench-gui
mkdir -p "$dir"
# The desktop program reads model files only: write the benchmark models with the overrides applied.
python3 - "$dir" <<'PY'
import json, sys
out = sys.argv[1]
def write(source, name, changes):
    m = json.load(open(source))
    for path, value in changes:
        node = m
        keys = path.strip("/").split("/")
        for k in keys[:-1]:
            node = node[int(k)] if isinstance(node, list) else node[k]
        last = keys[-1]
        if isinstance(node, list): node[int(last)] = value
        else: node[last] = value
    json.dump(m, open(f"{out}/{name}.json", "w"), indent=1)
write("examples/kirsch.json", "kirsch-104k",
      [("/mesh/size", 0.14), ("/mesh/local", []), ("/analysis/steps", 20)])
write("examples/salencon-tunnel.json", "salencon-53k",
      [("/mesh/local/0/size", 0.036), ("/mesh/local/0/radius", 4), ("/mesh/size", 0.8)])
PY
run_gui() {
  if [ -n "${DISPLAY:-}" ]; then "$gui" --run --quit-after-run "$1"
  else xvfb-run -a -s "-screen 0 1600x1000x24" "$gui" --run --quit-after-run "$1"; fi
}
printf '%-14s %-9s %12s %10s %10s\n' model program solver_s wall_s CPU_s
for model in kirsch-104k salencon-53k; do
  for ((i = 1; i <= repeat; ++i)); do
    for program in headless desktop; do
      if [ $program = headless ]; then
        res=$( { /usr/bin/time -f 'RESOURCES %e %U %S' "$mcdda" run "$dir/$model.json" --out "$dir/$model-results" --quiet; } 2>&1 | grep RESOURCES )
      else
        res=$( { /usr/bin/time -f 'RESOURCES %e %U %S' bash -c "$(declare -f run_gui); gui=$gui run_gui $dir/$model.json" >/dev/null; } 2>&1 | grep RESOURCES )
      fi
      read -r _ wall user sys <<<"$res"
      solver=$(python3 -c "import json; print(round(json.load(open('$dir/$model-results/summary.json'))['timing']['total'], 3))")
      printf '%-14s %-9s %12s %10s %10s\n' "$model" "$program" "$solver" "$wall" "$(python3 -c "print(round($user + $sys, 2))")"
    done
  done
done
