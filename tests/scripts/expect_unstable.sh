#!/usr/bin/env bash
# expect_unstable.sh OUTDIR [--ranks "1 2" --mpirun MPIEXEC] [PATTERN...] -- COMMAND...
# COMMAND must exit with 4 and print one diagnosis line ("the run went unstable: ...") that matches every PATTERN
# (grep -E), summary.json must say "unstable", and no dump may hold a NaN. With --ranks, COMMAND runs once per rank
# count (N > 1 under "MPIEXEC --oversubscribe --allow-run-as-root -np N", into OUTDIR_npN) and the diagnosis text
# must be the same on all of them: the cell is named by its global id, the values are bitwise the same.
set -u
out=$1; shift
ranks="1"; mpirun=""; patterns=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    case "$1" in
        --ranks) ranks=$2; shift 2 ;;
        --mpirun) mpirun=$2; shift 2 ;;
        *) patterns+=("$1"); shift ;;
    esac
done
[ "${1:-}" = "--" ] || { echo "usage: expect_unstable.sh OUTDIR [--ranks LIST --mpirun MPIEXEC] [PATTERN...] -- COMMAND..."; exit 1; }
shift
first=""
for np in $ranks; do
    dir=$out; launch=()
    if [ "$np" != 1 ]; then
        dir=${out}_np$np
        launch=("$mpirun" --oversubscribe --allow-run-as-root -np "$np")
    fi
    rm -rf "$dir"
    err=$("${launch[@]}" "$@" --output "$dir" 2>&1 >/dev/null); rc=$?
    echo "$np rank(s): exit $rc: $err"
    [ "$rc" -eq 4 ] || { echo "FAIL: expected exit code 4"; exit 1; }
    diag=$(echo "$err" | grep "went unstable")
    [ -n "$diag" ] || { echo "FAIL: no diagnosis"; exit 1; }
    [ "$(echo "$diag" | wc -l)" -eq 1 ] || { echo "FAIL: expected one diagnosis line (rank 0's), found several"; exit 1; }
    for p in "${patterns[@]}"; do
        echo "$diag" | grep -qE "$p" || { echo "FAIL: diagnosis does not match '$p'"; exit 1; }
    done
    if [ -z "$first" ]; then
        first=$diag
    elif [ "$diag" != "$first" ]; then
        printf 'FAIL: the diagnosis on %s ranks differs from the first run:\n  %s\n  %s\n' "$np" "$first" "$diag"; exit 1
    fi
    grep -q '"status": "unstable"' "$dir/summary.json" || { echo "FAIL: summary.json does not say unstable"; exit 1; }
    /usr/bin/python3 - "$dir" <<'PY' || exit 1
import glob, sys
import h5py, numpy as np
for f in sorted(glob.glob(sys.argv[1] + "/unilag_*.h5")):
    with h5py.File(f) as h:
        for k in h:
            if not np.all(np.isfinite(h[k][...])):
                sys.exit(f"FAIL: {f}:{k} holds non-finite values")
print("no NaN in", len(glob.glob(sys.argv[1] + "/unilag_*.h5")), "dumps")
PY
done
echo "expect_unstable: PASS"
