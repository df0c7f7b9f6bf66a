#!/bin/sh
# Runs a test program under a virtual X server: under-xvfb.sh XVFB_RUN PROGRAM [ARGS...].
# xvfb-run keeps its authority file in a temporary folder of its own and, when removing that
# folder fails (seen now and then in CI), exits with status 5 instead of the program's. Given an
# authority file of ours (-f) it makes no folder, so the status is always the program's.
xvfb_run=$1
shift
auth=$(mktemp) || exit 1
"$xvfb_run" -a -f "$auth" -s "-screen 0 1280x1024x24" "$@"
status=$?
rm -f "$auth"
exit $status
