#!/usr/bin/env python3
"""Period of the vibrating beryllium plate (docs/gpr-model.md 3.9, inputs/be_plate2d.yaml) from a run's dumps: the
vertical velocity at the plate centre (mass average over the cells whose first-dump centroid lies within RADIUS of the
origin) against time, its zero crossings interpolated linearly, the period = 2 x the mean spacing of consecutive
crossings. Passes iff |period - EXPECTED_PERIOD| <= TOL * EXPECTED_PERIOD (and at least 3 crossings were found).
EXPECTED_PERIOD comes from tests/scripts/plate_reference_period.py (28.89e-6 s for the scene's material).

With LO HI, the centre-velocity amplitude at the last extremum must also lie within [LO, HI] times the one at the
first (numerical damping or growth of the mode).

usage: plate_period.py OUTDIR EXPECTED_PERIOD TOL [RADIUS [LO HI]]
"""
import glob
import re
import sys

import h5py
import numpy as np

out, expected, tol = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
radius = float(sys.argv[4]) if len(sys.argv) > 4 else 1.5e-3
bounds = (float(sys.argv[5]), float(sys.argv[6])) if len(sys.argv) > 6 else None
h5s = sorted(glob.glob(f"{out}/unilag_*.h5"))
times, vc, vmean = [], [], []
pick = None
for path in h5s:
    with open(path[:-3] + ".xmf") as f:
        times.append(float(re.search(r'<Time Value="([^"]+)"', f.read()).group(1)))
    with h5py.File(path, "r") as f:
        # cells in global order, so that the same cells are followed whatever the partition
        order = np.argsort(f["global_id"][:, 0]) if "global_id" in f else slice(None)
        xyz, conn = f["coordinates"][...], f["connectivity"][...][order]
        m = (f["density"][:, 0] * f["volume"][:, 0])[order]
        vy = f["velocity"][:, 1][order]
    if pick is None:
        c = xyz[conn].mean(axis=1)
        pick = np.hypot(c[:, 0], c[:, 1]) < radius
        print(f"{np.count_nonzero(pick)} cells within {radius:g} m of the centre")
    vc.append(np.average(vy[pick], weights=m[pick]))
    vmean.append(np.average(vy, weights=m))
times, vc = np.array(times), np.array(vc)
print(f"{len(times)} dumps, t = {times[0]:.3g} .. {times[-1]:.3g} s; centre v_y(0) = {vc[0]:.4g} m/s, "
      f"|mean v_y| <= {np.max(np.abs(vmean)):.2e} m/s")
s = np.sign(vc)
idx = np.nonzero(s[:-1] * s[1:] < 0)[0]
crossings = times[idx] - vc[idx] * (times[idx + 1] - times[idx]) / (vc[idx + 1] - vc[idx])
print("zero crossings (us):", " ".join(f"{c * 1e6:.3f}" for c in crossings))
ok = len(crossings) >= 3
if ok:
    halves = np.diff(crossings)
    period = 2.0 * halves.mean()
    err = abs(period - expected) / expected
    print(f"half periods (us): {' '.join(f'{x * 1e6:.3f}' for x in halves)}")
    print(f"period {period * 1e6:.3f} us, expected {expected * 1e6:.3f} us: error {err:.2%} (tolerance {tol:.0%})")
    ok = err <= tol
    # amplitude of the centre velocity at successive extrema (numerical damping)
    ext = [np.max(np.abs(vc[(times >= a) & (times <= b)])) for a, b in zip(crossings, crossings[1:])]
    print("centre |v_y| extrema (m/s):", " ".join(f"{e:.3f}" for e in ext))
    if bounds is not None:
        ratio = ext[-1] / ext[0]
        print(f"last / first extremum {ratio:.3f} (bounds {bounds[0]:g} .. {bounds[1]:g})")
        ok = ok and bounds[0] <= ratio <= bounds[1]
else:
    print("FAIL: fewer than 3 zero crossings; run longer")
print("plate_period:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
