#!/bin/sh
# `mcdda render` into a folder the user may not write to says so in words (VTK's
# "Ran out of disk space" and a wrong errno before), with no file left behind.
# Usage: render-unwritable.sh MCDDA RUN_DIR EXAMPLES_DIR
set -u
mcdda=$1 dir=$2/render-unwritable examples=$3
rm -rf "$dir" && mkdir -p "$dir" && chmod 555 "$dir"
as_user=""
if [ "$(id -u)" -eq 0 ]; then
  setpriv --reuid=65534 --regid=65534 --clear-groups "$mcdda" --version >/dev/null 2>&1 \
    || { echo "skipped: cannot run as another user here"; exit 0; }
  as_user="setpriv --reuid=65534 --regid=65534 --clear-groups"
fi
out=$($as_user "$mcdda" render "$examples/kirsch.json" --out "$dir/kirsch.png" 2>&1)
code=$?
echo "$out"
chmod 755 "$dir"
[ $code -eq 6 ] || { echo "FAILED: exit status $code"; exit 1; }
echo "$out" | grep -q "cannot write $dir/kirsch.png: Permission denied" || { echo "FAILED: message"; exit 1; }
echo "$out" | grep -q "disk space" && { echo "FAILED: VTK's wording"; exit 1; }
[ -z "$(ls -A "$dir")" ] || { echo "FAILED: files left behind"; exit 1; }
echo ok
