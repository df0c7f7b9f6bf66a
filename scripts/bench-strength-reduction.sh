#!/usr/bin/env bash
# Strength reduction benchmark: the factor-of-safety search of the two shipped c-φ slopes
# (associated flow and ψ = 0 by Davis's reduction) against one static solve of the same model at
# F = 1, in CPU time of the whole process, one thread. With MCDDA_BEFORE=path/to/mcdda the same
# rows are run with that build too, one after the other, for a side-by-side table
# (docs/benchmarks.md, "Strength reduction: the search against one static solve").
# Usage: bash scripts/bench-strength-reduction.sh [MODEL.json...]
#        (default: examples/homogeneous-slope.json examples/slope-griffiths-lane.json)
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
models=("$@")
[ ${#models[@]} -gt 0 ] || models=(examples/homogeneous-slope.json examples/slope-griffiths-lane.json)
builds=("$mcdda")
[ -n "${MCDDA_BEFORE:-}" ] && builds=("$MCDDA_BEFORE" "$mcdda")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cpu() {  # CPU seconds (user + system) of one mcdda run; its summary in $work/out
  rm -rf "$work/out"
  /usr/bin/time -f "%U %S" -o "$work/time" "$@" --out "$work/out" --threads 1 --quiet >/dev/null 2>&1 || true
  tail -1 "$work/time" | awk '{printf "%.2f", $1 + $2}'   # (after a line on a non-zero exit status)
}

echo "| build | model | flow | one static solve (s) | search (s) | trials | factor | search / solve |"
echo "|---|---|---|---|---|---|---|---|"
for model in "${models[@]}"; do
  for flow in associated davis; do
    # ψ = φ (the file's friction angle), or ψ = 0 solved by Davis's reduction (the default).
    if [ "$flow" = associated ]; then
      phi=$(python3 -c "import json; print(json.load(open('$model'))['materials'][0]['friction_angle'])")
      set_flow=(--set "/materials/0/dilation_angle=$phi")
    else
      set_flow=(--set /materials/0/dilation_angle=0)
    fi
    for build in "${builds[@]}"; do
      solve=$(cpu "$build" run "$model" "${set_flow[@]}" --set '/analysis/type="static"')
      search=$(cpu "$build" run "$model" "${set_flow[@]}")
      read -r trials factor < <(python3 -c "
import json
f = json.load(open('$work/out/summary.json')).get('factor_of_safety', {})
print(f.get('trials', '-'), '%.4f' % f['value'] if 'value' in f else '-')")
      ratio=$(python3 -c "print('%.0f' % ($search / max($solve, 1e-3)))")
      echo "| $build | $(basename "$model") | $flow | $solve | $search | $trials | $factor | $ratio |"
    done
  done
done
