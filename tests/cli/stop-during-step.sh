#!/bin/sh
# SIGTERM during one long step (the flexible footing loaded past collapse in one step on a fine
# mesh: the step halves its load increment and iterates for many seconds) ends the run within
# seconds, cancelled, with the results of the last increment accepted; it does not wait for the
# step to end.
# Usage: stop-during-step.sh MCDDA MODEL WORKDIR
mcdda=$1; model=$2; dir=$3/stop-during-step
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$dir"
"$mcdda" run "$model" --out "$dir" --quiet --set /analysis/steps=1 &
pid=$!
# Into the step: its first files (step 0) are written before it starts.
i=0
while [ ! -f "$dir/summary.json" ] && [ ! -f "$dir/history.csv" ] && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
sleep 2
kill -0 $pid 2>/dev/null || fail "the run ended before it could be stopped"
kill -TERM $pid
i=0
while kill -0 $pid 2>/dev/null && [ $i -lt 100 ]; do sleep 0.1; i=$((i + 1)); done
if kill -0 $pid 2>/dev/null; then kill -9 $pid; fail "still running 10 s after SIGTERM"; fi
wait $pid; code=$?
[ $code -eq 130 ] || fail "exit status $code, not 130"
grep -q '"status": "cancelled"' "$dir/summary.json" || fail "summary.json does not say cancelled"
grep -q 'during step 1' "$dir/summary.json" || fail "summary.json does not say the step it stopped in"
grep -q '</VTKFile>' "$dir"/*.pvd || fail "no complete collection file"
echo "stopped within $((i / 10)).$((i % 10)) s of SIGTERM"
