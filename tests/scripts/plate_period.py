#!/usr/bin/env python3
"""Checks the vibrating beryllium plate's period (apps/plate_period.py: the centre velocity's zero crossings; docs/
gpr-model.md 3.9, inputs/be_plate2d.yaml). Passes iff |period - EXPECTED_PERIOD| <= TOL * EXPECTED_PERIOD (and at
least 3 crossings were found). EXPECTED_PERIOD comes from tests/scripts/plate_reference_period.py (28.89e-6 s for the
scene's material).

With LO HI, the centre-velocity amplitude at the last extremum must also lie within [LO, HI] times the one at the
first (numerical damping or growth of the mode).

usage: plate_period.py OUTDIR EXPECTED_PERIOD TOL [RADIUS [LO HI]]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps"))
from plate_period import period  # noqa: E402

out, expected, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
radius = float(sys.argv[4]) if len(sys.argv) > 4 else 1.5e-3
bounds = (float(sys.argv[5]), float(sys.argv[6])) if len(sys.argv) > 6 else None
value, crossings, extrema = period(out, radius)
ok = value == value
if ok:
    err = abs(value - expected) / expected
    print(f"period {value * 1e6:.3f} us, expected {expected * 1e6:.3f} us: error {err:.2%} (tolerance {tol:.1%})")
    ok = err <= tol
    if bounds is not None:
        ratio = extrema[-1] / extrema[0]
        print(f"last / first extremum {ratio:.3f} (bounds {bounds[0]:g} .. {bounds[1]:g})")
        ok = ok and bounds[0] <= ratio <= bounds[1]
else:
    print("FAIL: fewer than 3 zero crossings; run longer")
print("plate_period:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
