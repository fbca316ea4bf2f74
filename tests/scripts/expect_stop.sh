#!/usr/bin/env bash
# expect_stop.sh OUTDIR CASE -- COMMAND...: runs COMMAND --output OUTDIR and asserts how the run stops.
#   write_failure: a folder already sits where dump 1 goes (OUTDIR/unilag_000001.h5), so the writer fails mid-run:
#                  exit 2, one error line naming that file, no summary.json.
#   disk_full:     dump 1 is a link to /dev/full (every write fails: no space left), so HDF5 fails mid-write and
#                  cannot close the file: the same (it crashed in MPI_Finalize, exit 139).
#   summary_in_the_way, steps_full: a folder where summary.json goes, or steps.csv a link to /dev/full: exit 2, one
#                  line naming that file (both were silent, exit 0).
#   max_steps:     COMMAND caps the steps (time.max_steps): exit 5, a line saying so, status "max_steps" in
#                  summary.json.
set -u
out=$1; case=$2; shift 3
rm -rf "$out"
want=2; unwritten="the output could not be written"
case "$case" in
    write_failure)      mkdir -p "$out/unilag_000001.h5"; pattern="$unwritten: .*unilag_000001.h5" ;;
    disk_full)          mkdir -p "$out" && ln -s /dev/full "$out/unilag_000001.h5"
                        pattern="$unwritten: .*unilag_000001.h5" ;;
    summary_in_the_way) mkdir -p "$out/summary.json"; pattern="$unwritten: cannot write .*summary.json" ;;
    steps_full)         mkdir -p "$out" && ln -s /dev/full "$out/steps.csv"
                        pattern="$unwritten: cannot write .*steps.csv" ;;
    *)                  want=5; pattern="stopped: time.max_steps = [0-9]+ reached at t = " ;;
esac
err=$("$@" --output "$out" 2>&1 >/dev/null); rc=$?
echo "exit $rc: $err"
[ "$rc" -eq "$want" ] || { echo "FAIL: expected exit code $want"; exit 1; }
echo "$err" | grep -qE -e "$pattern" || { echo "FAIL: message does not match '$pattern'"; exit 1; }
[ "$(echo "$err" | grep -c 'unilag:')" -eq 1 ] || { echo "FAIL: expected exactly one message line"; exit 1; }
if [ "$case" = write_failure ] || [ "$case" = disk_full ] || [ "$case" = steps_full ]; then
    [ ! -e "$out/summary.json" ] || { echo "FAIL: a summary.json was written"; exit 1; }
elif [ "$case" = summary_in_the_way ]; then
    [ -d "$out/summary.json" ] || { echo "FAIL: the folder in summary.json's place is gone"; exit 1; }
else
    grep -q '"status": "max_steps"' "$out/summary.json" || { echo "FAIL: summary.json status is not max_steps"; exit 1; }
fi
echo "expect_stop: PASS"
