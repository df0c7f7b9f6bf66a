#!/usr/bin/env bash
# The held factor's single-precision solves, this tree's kernels against REV's, side by side:
# scripts/bench-held-solve.cpp is built once against each version of
# solver/linalg/SinglePrecisionFactor.{hpp,cpp} and the two run one after the other, ROUNDS
# times on the same core. Equal checksums mean the same answers to the last bit.
# Usage: bash scripts/bench-held-solve.sh [REV [ROUNDS [SUPERNODAL_SWITCH]]]
#        (default HEAD, 3 rounds, 300: the solver's switch, a simplicial factor; 40 gives a supernodal one)
set -euo pipefail
cd "$(dirname "$0")/.."
rev=${1:-HEAD}
rounds=${2:-3}
switch=${3:-300}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/old/linalg" "$work/new/linalg"
git show "$rev:solver/linalg/SinglePrecisionFactor.hpp" > "$work/old/linalg/SinglePrecisionFactor.hpp"
git show "$rev:solver/linalg/SinglePrecisionFactor.cpp" > "$work/old/linalg/SinglePrecisionFactor.cpp"
cp solver/linalg/SinglePrecisionFactor.hpp solver/linalg/SinglePrecisionFactor.cpp "$work/new/linalg/"
for version in old new; do
  g++ -O3 -std=c++17 -DNDEBUG -I"$work/$version" -I/usr/include/eigen3 -I/usr/include/suitesparse \
    scripts/bench-held-solve.cpp "$work/$version/linalg/SinglePrecisionFactor.cpp" -o "$work/bench-$version" -lcholmod
done
for round in $(seq "$rounds"); do
  echo "$rev:       $(taskset -c 0 "$work/bench-old" "$switch")"
  echo "this tree: $(taskset -c 0 "$work/bench-new" "$switch")"
done
