#!/usr/bin/env bash
# Installs dependencies, configures and builds mcdda into ./build (Release, with tests).
# Safe to run again: an existing build directory is reused and only changes are rebuilt.
set -euo pipefail
cd "$(dirname "$0")/.."

bash scripts/install-dependencies.sh
generator=()
if command -v ninja >/dev/null 2>&1 && [ ! -f build/Makefile ]; then generator=(-G Ninja); fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DMCDDA_BUILD_TESTS=ON > build-configure.log 2>&1 \
  || { cat build-configure.log; exit 1; }
rm -f build-configure.log
cmake --build build --parallel "$(nproc)"
