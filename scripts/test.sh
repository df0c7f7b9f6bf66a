#!/usr/bin/env bash
# Quick start (b): builds mcdda and runs the whole test suite (unit, validation, CLI and GUI
# tests; GUI and rendering tests start their own virtual X server).
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/build.sh
source scripts/blas-core.sh
cd build
ctest --output-on-failure --parallel "$(nproc)" --timeout 1500
