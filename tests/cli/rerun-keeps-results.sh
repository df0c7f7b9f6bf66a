#!/bin/sh
# A rerun into a folder with results: killed or failed, it leaves the earlier results
# in DIR/previous; completed, it replaces them.
# Usage: rerun-keeps-results.sh MCDDA RUN_DIR EXAMPLES_DIR CLI_MODELS_DIR
set -u
mcdda=$1 dir=$2/keep examples=$3 models=$4
fail() { echo "FAILED: $*"; exit 1; }
rm -rf "$dir"
"$mcdda" run "$examples/kirsch.json" --out "$dir" --quiet || fail "first run"

# Killed (SIGKILL) once its first step file is written.
"$mcdda" run "$examples/jointed-tunnel.json" --out "$dir" --quiet --set /analysis/steps=100000 &
pid=$!
i=0
while [ ! -f "$dir/jointed-tunnel_000000.vtu" ] && [ $i -lt 300 ]; do sleep 0.1; i=$((i + 1)); done
kill -9 $pid; wait $pid 2>/dev/null
[ -f "$dir/jointed-tunnel_000000.vtu" ] || fail "the killed run never started writing"
[ -f "$dir/previous/kirsch_000005.vtu" ] || fail "killed rerun: kirsch_000005.vtu not kept"
grep -q '"status": "completed"' "$dir/previous/summary.json" || fail "killed rerun: summary not kept"
[ "$(wc -l < "$dir/previous/history.csv")" -eq 7 ] || fail "killed rerun: history not kept whole"

# Failed (a mechanism): the kept results stay, and the message says where they are.
out=$("$mcdda" run "$models/free-block.json" --out "$dir" --quiet 2>&1)
code=$?
echo "$out"
[ $code -eq 4 ] || fail "free block: exit status $code"
echo "$out" | grep -q "earlier results are kept in $dir/previous" || fail "no word on the kept results"
[ -f "$dir/previous/kirsch_000005.vtu" ] || fail "failed rerun: kirsch results not kept"
[ ! -f "$dir/jointed-tunnel_000000.vtu" ] || fail "the killed run's files are still there"

# Completed: its results replace the kept ones.
"$mcdda" run "$examples/kirsch.json" --out "$dir" --quiet --set /analysis/steps=2 || fail "last run"
[ ! -e "$dir/previous" ] || fail "previous/ not removed after a completed run"
[ -f "$dir/kirsch_000002.vtu" ] && [ ! -f "$dir/kirsch_000005.vtu" ] || fail "step files of the last run"
grep -q '"status": "completed"' "$dir/summary.json" || fail "summary of the last run"

# A folder the user may not write to: refused with the reason, the results untouched. (Root
# ignores permissions: as root the run is made as nobody, where setpriv can do that.)
as_user=""
if [ "$(id -u)" -eq 0 ]; then
  if setpriv --reuid=65534 --regid=65534 --clear-groups "$mcdda" --version >/dev/null 2>&1; then
    as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
  else
    echo "unwritable folder: skipped (cannot run as another user here)"; echo "ok"; exit 0
  fi
fi
chmod 555 "$dir"
out=$($as_user "$mcdda" run "$examples/kirsch.json" --out "$dir" --quiet 2>&1)
code=$?
chmod 755 "$dir"
echo "$out"
[ $code -eq 6 ] || fail "unwritable folder: exit status $code"
echo "$out" | grep -q "cannot write into the output directory $dir: Permission denied" || fail "unwritable: message"
[ "$(wc -l < "$dir/history.csv")" -eq 4 ] && [ -f "$dir/kirsch_000002.vtu" ] || fail "unwritable: results touched"
echo "ok"
