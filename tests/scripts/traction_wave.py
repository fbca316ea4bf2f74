#!/usr/bin/env python3
"""Check a wave driven by an imposed traction: mean x-velocity behind the front and the front position (where the
velocity crosses half of its value behind), from the last dump of a run.

usage: traction_wave.py OUTDIR U_BEHIND X_FRONT X_BEHIND TOL [TOL_FRONT]
TOL bounds the relative error of the velocity behind the front; TOL_FRONT (default TOL) that of its position.
  U_BEHIND  exact velocity behind the front
  X_FRONT   exact front position
  X_BEHIND  cells with centroid x < X_BEHIND are "behind" (clear of the smeared front)
"""
import glob
import sys

import h5py
import numpy as np

out, u_exact, x_front, x_behind, tol = sys.argv[1], *map(float, sys.argv[2:6])
tol_front = float(sys.argv[6]) if len(sys.argv) > 6 else tol
with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
    xyz, conn = f["coordinates"][...], f["connectivity"][...]
    u, vol = f["velocity"][:, 0], f["volume"][:, 0]
xc = xyz[conn][:, :, 0].mean(axis=1)
behind = xc < x_behind
ub = np.average(u[behind], weights=vol[behind])
# front: volume-weighted mean velocity in thin x bins, first bin below half of ub going right
bins = np.linspace(xc.min(), xc.max(), 81)
idx = np.digitize(xc, bins)
prof = np.array([np.average(u[idx == k], weights=vol[idx == k]) if np.any(idx == k) else np.nan for k in range(1, len(bins))])
centres = 0.5 * (bins[1:] + bins[:-1])
k = int(np.argmax(prof < 0.5 * ub))
xf = centres[k - 1] + (centres[k] - centres[k - 1]) * (prof[k - 1] - 0.5 * ub) / (prof[k - 1] - prof[k])
ok = True
for name, got, want in (("velocity behind", ub, u_exact), ("front position", xf, x_front)):
    err = abs(got - want) / abs(want)
    bound = tol_front if name == "front position" else tol
    print(f"{name}: {got:.6g} (exact {want:.6g}, error {err:.2%}, bound {bound:.2%})")
    ok &= err <= bound
print("traction_wave:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
