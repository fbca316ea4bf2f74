#!/usr/bin/env bash
# expect_check_failure.sh OUTDIR REGEX -- COMMAND...: COMMAND (a run with --check) must complete, write its summary,
# and exit 3 with a "check failed" line on stderr matching REGEX.
set -u
out=$1 regex=$2; shift 3
rm -rf "$out"
err=$("$@" --output "$out" 2>&1 >/dev/null); rc=$?
echo "exit $rc: $err"
[ "$rc" -eq 3 ] || { echo "FAIL: expected exit code 3 (a failed check)"; exit 1; }
echo "$err" | grep -Eq "unilag: check failed: $regex" || { echo "FAIL: no 'check failed' line matching: $regex"; exit 1; }
[ -f "$out/summary.json" ] || { echo "FAIL: no summary.json: a failed check still reports the run"; exit 1; }
echo "expect_check_failure: PASS"
