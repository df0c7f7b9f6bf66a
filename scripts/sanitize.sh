#!/usr/bin/env bash
# Builds the solver, the command line and their tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (build-sanitize/, RelWithDebInfo) and runs the tests; any memory
# error, leak or undefined behaviour in mcdda's code fails them.
#   bash scripts/sanitize.sh                      solver and CLI tests (about 6 minutes on 2 cores
#                                                 after the build)
#   bash scripts/sanitize.sh "solver|cli|validation"   the validation tests too (much longer)
# Not checked: UBSan's vptr check (CGAL's arrangement DCEL downcasts between its own record types
# trip it throughout), and a 45 KB allocation libstdc++ keeps for the life of every process
# (scripts/sanitize-suppressions.txt). The desktop program is not built here.
set -euo pipefail
cd "$(dirname "$0")/.."
labels=${1:-"solver|cli"}
bash scripts/install-dependencies.sh
flags="-fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
mkdir -p build-sanitize
cmake -S . -B build-sanitize -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMCDDA_BUILD_GUI=OFF -DMCDDA_BUILD_TESTS=ON \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" > build-sanitize/configure.log 2>&1 \
  || { cat build-sanitize/configure.log; exit 1; }
cmake --build build-sanitize
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/sanitize-suppressions.txt:print_suppressions=0"
ctest --test-dir build-sanitize -L "$labels" --output-on-failure --parallel 2 --timeout 3000
