#!/usr/bin/env bash
# Elastic throughput benchmark: the Kirsch plate (examples/kirsch.json, one block, updated
# geometry, 5 static steps) meshed uniformly at several sizes. Prints per size the elements, time
# per step, one factorisation, the step / factorisation ratio, factorisations and held-factor
# solves, CPU time and peak memory. OLD=path/to/mcdda runs every size with that build too, row
# by row (side by side, one session). BLAS=reference runs on the reference BLAS instead of
# OpenBLAS (Debian's alternatives are left alone: LD_LIBRARY_PATH points at the netlib copies).
# Usage: bash scripts/bench-kirsch.sh [SIZES...]   (element sizes in m; default "0.435 0.196 0.0998":
#        about 10k, 53k and 205k triangles; 0.0453 gives about a million)
set -euo pipefail
cd "$(dirname "$0")/.."
mcdda=${MCDDA:-build/app/mcdda}
[ -x "$mcdda" ] || bash scripts/build.sh
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(0.435 0.196 0.0998)
builds=("$mcdda")
[ -n "${OLD:-}" ] && builds+=("$OLD")
if [ "${BLAS:-}" = reference ]; then
  export LD_LIBRARY_PATH=/usr/lib/x86_64-linux-gnu/blas:/usr/lib/x86_64-linux-gnu/lapack${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
fi
mkdir -p out
printf '%-8s %-28s %9s %9s %9s %7s %14s %8s %8s\n' size build elements s/step factor step/f "factors+held" CPU_s RSS_MB
for size in "${sizes[@]}"; do
  for build in "${builds[@]}"; do
    dir="out/bench-kirsch-$size"
    log=$(/usr/bin/time -f 'RESOURCES %M %U %S' "$build" run examples/kirsch.json --out "$dir" --quiet --profile \
      --set /mesh/size="$size" --set /mesh/local=[] --set /analysis/output_every=1000 2>&1)
    elements=$(python3 -c "import json; print(json.load(open('$dir/summary.json'))['model']['elements'])")
    per_step=$(sed -n 's/^per step \([0-9.e+-]*\) s; one factorization \([0-9.e+-]*\) s; step \/ factorization = \([0-9.e+-]*\)$/\1 \2 \3/p' <<<"$log")
    counts=$(sed -n 's/^factorizations \([0-9]*\) .*; \([0-9]*\) matrices solved with a held factor.*/\1+\2/p' <<<"$log")
    [ -n "$counts" ] || counts=$(sed -n 's/^factorizations \([0-9]*\) .*/\1/p' <<<"$log")
    read -r rss user sys < <(sed -n 's/^RESOURCES //p' <<<"$log")
    read -r step factor ratio <<<"$per_step"
    printf '%-8s %-28s %9s %9.3f %9.3f %7.2f %14s %8.1f %8.0f\n' "$size" "$(basename "$(dirname "$(dirname "$build")")")" \
      "$elements" "$step" "$factor" "$ratio" "$counts" "$(python3 -c "print($user + $sys)")" "$((rss / 1024))"
  done
done
