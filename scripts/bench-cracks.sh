#!/usr/bin/env bash
# Meshing benchmark with cracks: a 120 m × 60 m rock mass with one joint set of persistence 0.5
# (2 m joints, 2 m rock bridges, 0.92 m apart): 2,001 joints that end in the rock, each a crack
# inside the block, meshed with refinement towards their 4,002 tips. Prints the timing breakdown
# of `mcdda mesh --profile`. Usage: bash scripts/bench-cracks.sh [SPACING]   (default 0.92 m)
set -euo pipefail
cd "$(dirname "$0")/.."
spacing=${1:-0.92}
mcdda=${MCDDA:-build/app/mcdda}   # MCDDA=path/to/mcdda to use another build
[ -x "$mcdda" ] || bash scripts/build.sh
mkdir -p out/bench
cat > out/bench/cracks.json <<'MODEL'
{
  "format": "mcdda-model", "version": 1,
  "name": "rock mass with 2,000 non-persistent joints",
  "materials": [{"name": "rock", "young_modulus": 1e10, "poisson_ratio": 0.25, "unit_weight": 26000,
                 "cohesion": 1e6, "friction_angle": 40, "dilation_angle": 10}],
  "joint_materials": [{"name": "joint", "friction_angle": 30}],
  "default_joint_material": "joint",
  "regions": [{"name": "rock mass", "material": "rock", "boundary": [[0,0],[120,0],[120,60],[0,60]]}],
  "joint_sets": [{"name": "bedding", "angle": 20, "spacing": 0.92, "origin": [0.3, 0.2],
                  "persistence": 0.5, "trace_length": 2.0, "stagger": 0.37}],
  "rollers": [{"name": "base", "from": [0,0], "to": [120,0], "fixed": "xy"}],
  "mesh": {"size": 2.0, "min_angle": 28}
}
MODEL
"$mcdda" check out/bench/cracks.json --set /joint_sets/0/spacing="$spacing"
"$mcdda" mesh out/bench/cracks.json --out out/bench --set /joint_sets/0/spacing="$spacing" --profile
