#!/usr/bin/env bash
# expect_stop.sh OUTDIR CASE -- COMMAND...: runs COMMAND --output OUTDIR and asserts how the run stops.
#   write_failure: a folder already sits where dump 1 goes (OUTDIR/unilag_000001.h5), so the writer fails mid-run:
#                  exit 2, one error line naming that file, no summary.json.
#   max_steps:     COMMAND caps the steps (time.max_steps): exit 5, a line saying so, status "max_steps" in
#                  summary.json.
set -u
out=$1; case=$2; shift 3
rm -rf "$out"
if [ "$case" = write_failure ]; then
    mkdir -p "$out/unilag_000001.h5"
    want=2; pattern="the output could not be written: .*unilag_000001.h5"
else
    want=5; pattern="stopped: time.max_steps = [0-9]+ reached at t = "
fi
err=$("$@" --output "$out" 2>&1 >/dev/null); rc=$?
echo "exit $rc: $err"
[ "$rc" -eq "$want" ] || { echo "FAIL: expected exit code $want"; exit 1; }
echo "$err" | grep -qE -e "$pattern" || { echo "FAIL: message does not match '$pattern'"; exit 1; }
[ "$(echo "$err" | grep -c 'unilag:')" -eq 1 ] || { echo "FAIL: expected exactly one message line"; exit 1; }
if [ "$case" = write_failure ]; then
    [ ! -e "$out/summary.json" ] || { echo "FAIL: a summary.json was written"; exit 1; }
else
    grep -q '"status": "max_steps"' "$out/summary.json" || { echo "FAIL: summary.json status is not max_steps"; exit 1; }
fi
echo "expect_stop: PASS"
