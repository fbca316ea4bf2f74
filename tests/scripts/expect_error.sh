#!/usr/bin/env bash
# expect_error.sh OUTDIR PATTERN -- COMMAND...: COMMAND must exit with 2, print PATTERN (grep -E) on stderr in one
# line, and leave OUTDIR uncreated (no partial output).
set -u
out=$1; pattern=$2; shift 3
rm -rf "$out"
err=$("$@" --output "$out" 2>&1 >/dev/null); rc=$?
echo "exit $rc: $err"
[ "$rc" -eq 2 ] || { echo "FAIL: expected exit code 2"; exit 1; }
echo "$err" | grep -qE -e "$pattern" || { echo "FAIL: message does not match '$pattern'"; exit 1; }
[ "$(echo "$err" | grep -c 'error')" -eq 1 ] || { echo "FAIL: expected exactly one error line"; exit 1; }
[ ! -e "$out" ] || { echo "FAIL: output folder $out was created"; exit 1; }
echo "expect_error: PASS"
