#!/usr/bin/env bash
# expect_unstable.sh OUTDIR -- COMMAND...: COMMAND must exit with 4 and a diagnosis, and no dump may hold a NaN.
set -u
out=$1; shift 2
rm -rf "$out"
err=$("$@" --output "$out" 2>&1 >/dev/null); rc=$?
echo "exit $rc: $err"
[ "$rc" -eq 4 ] || { echo "FAIL: expected exit code 4"; exit 1; }
echo "$err" | grep -q "went unstable" || { echo "FAIL: no diagnosis"; exit 1; }
grep -q '"status": "unstable"' "$out/summary.json" || { echo "FAIL: summary.json does not say unstable"; exit 1; }
/usr/bin/python3 - "$out" <<'PY' || exit 1
import glob, sys
import h5py, numpy as np
for f in sorted(glob.glob(sys.argv[1] + "/unilag_*.h5")):
    with h5py.File(f) as h:
        for k in h:
            if not np.all(np.isfinite(h[k][...])):
                sys.exit(f"FAIL: {f}:{k} holds non-finite values")
print("no NaN in", len(glob.glob(sys.argv[1] + "/unilag_*.h5")), "dumps")
PY
echo "expect_unstable: PASS"
