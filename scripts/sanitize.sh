#!/usr/bin/env bash
# Builds the solver, the command line and their tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (build-sanitize/, RelWithDebInfo) and runs the tests; any memory
# error, leak or undefined behaviour in mcdda's code fails them.
#   bash scripts/sanitize.sh                      solver and CLI tests (about 6 minutes on 2 cores
#                                                 after the build)
#   bash scripts/sanitize.sh "solver|cli|validation"   the validation tests too (about 10 minutes more)
#   bash scripts/sanitize.sh tsan-solver          the solver's worker threads under ThreadSanitizer
#                                                 (build-tsan-solver/): any warning fails
#   bash scripts/sanitize.sh tsan                 the desktop program's run test (a worker thread
#                                                 solving while the window draws) under
#                                                 ThreadSanitizer in build-tsan/, with a count of
#                                                 the warnings that involve mcdda's own code
# Not checked: UBSan's vptr check (CGAL's arrangement DCEL downcasts between its own record types
# trip it throughout), and a 45 KB allocation libstdc++ keeps for the life of every process
# (scripts/sanitize-suppressions.txt). Qt, VTK and Mesa are not instrumented: ThreadSanitizer
# cannot see their locks and reports races inside them, so the tsan mode lists rather than fails.
set -euo pipefail
cd "$(dirname "$0")/.."
labels=${1:-"solver|cli"}
bash scripts/install-dependencies.sh

if [ "$labels" = tsan-solver ]; then
  # The solver's worker threads (parallel/ParallelFor): the pool's own tests and whole runs on
  # two threads, under ThreadSanitizer; any warning fails.
  mkdir -p build-tsan-solver
  cmake -S . -B build-tsan-solver -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMCDDA_BUILD_GUI=OFF -DMCDDA_BUILD_TESTS=ON \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" > build-tsan-solver/configure.log 2>&1 \
    || { cat build-tsan-solver/configure.log; exit 1; }
  cmake --build build-tsan-solver --target mcdda_solver_tests mcdda_validation_tests
  export TSAN_OPTIONS="halt_on_error=1 abort_on_error=1"
  build-tsan-solver/tests/solver/mcdda_solver_tests --gtest_filter='ParallelFor.*:SymmetricSystem.*'
  build-tsan-solver/tests/validation/mcdda_validation_tests --gtest_filter='SolverInvariants.OneAndTwoThreads*'
  exit $?
fi
if [ "$labels" = tsan ]; then
  mkdir -p build-tsan
  cmake -S . -B build-tsan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMCDDA_BUILD_GUI=ON -DMCDDA_BUILD_TESTS=ON \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_FLAGS="-fsanitize=thread -fno-omit-frame-pointer" \
    -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" > build-tsan/configure.log 2>&1 || { cat build-tsan/configure.log; exit 1; }
  cmake --build build-tsan --target test_run
  log=build-tsan/test_run.log
  status=0
  TSAN_OPTIONS="halt_on_error=0" xvfb-run -a -s "-screen 0 1280x1024x24" build-tsan/tests/gui/test_run > "$log" 2>&1 || status=$?
  grep -E '^(PASS|FAIL|Totals)' "$log"
  warnings=$(grep -c 'WARNING: ThreadSanitizer' "$log" || true)
  # The frame that made each racing access (the line after "Write"/"Read"), and the next one.
  ours=$(awk '/^  (Write|Read|Previous write|Previous read|Atomic)/{getline a; getline b; print a; print b}' "$log" \
         | grep -c '/gui/\|/solver/\|/app/' || true)
  echo "ThreadSanitizer: $warnings warnings; racing accesses made in mcdda's code: $ours (log: $log)"
  grep -q '^Totals: .* 0 failed' "$log" && [ "$ours" -eq 0 ]
  exit $?
fi
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
