#!/usr/bin/env python3
"""Check a piston-driven shock against the Rankine-Hugoniot state: mean density and pressure behind the shock and
the shock position (where density crosses half-way), from the last dump of a run.

usage: piston_shock.py OUTDIR RHO0 RHO1 P1 XSHOCK XPISTON TOL [TOL_SHOCK]
TOL bounds the relative errors of the states; TOL_SHOCK (default TOL) that of the shock position.
"""
import glob
import sys

import h5py
import numpy as np

out, rho0, rho1, p1, xs, xp, tol = sys.argv[1], *map(float, sys.argv[2:8])
tol_shock = float(sys.argv[8]) if len(sys.argv) > 8 else tol
with h5py.File(sorted(glob.glob(f"{out}/unilag_*.h5"))[-1], "r") as f:
    xyz, conn = f["coordinates"][...], f["connectivity"][...]
    rho, p, vol = f["density"][:, 0], f["pressure"][:, 0], f["volume"][:, 0]
xc = xyz[conn][:, :, 0].mean(axis=1)
ok = True
behind = (xc > xp + 0.2 * (xs - xp)) & (xc < xs - 0.2 * (xs - xp))
ahead = xc > xs + 0.2 * (1.0 - xs)
rb = np.average(rho[behind], weights=vol[behind])
pb = np.average(p[behind], weights=vol[behind])
ra = np.average(rho[ahead], weights=vol[ahead])
# shock position: cells sorted by x, first crossing of the half-way density from behind
order = np.argsort(xc)
half = 0.5 * (rho0 + rho1)
bins = np.linspace(xp, 1.0, 200)
idx = np.digitize(xc, bins)
prof = np.array([rho[idx == k].mean() if np.any(idx == k) else np.nan for k in range(1, len(bins))])
centres = 0.5 * (bins[1:] + bins[:-1])
k = np.nanargmax(np.where(prof < half, centres, -np.inf) > xp + 0.5 * (xs - xp))
x_shock = centres[k]
for name, got, want in (("density behind", rb, rho1), ("pressure behind", pb, p1), ("density ahead", ra, rho0),
                        ("shock position", x_shock, xs)):
    err = abs(got - want) / abs(want)
    bound = tol_shock if name == "shock position" else tol
    print(f"{name}: {got:.6g} (exact {want:.6g}, error {err:.2%}, bound {bound:.2%})")
    ok &= err <= bound
print("piston_shock:", "PASS" if ok else "FAIL")
sys.exit(0 if ok else 1)
