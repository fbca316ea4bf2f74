#!/usr/bin/env python3
"""Beryllium shell collapse (gpr.md 3.6, inputs/be_shell2d*.yaml) against the rigid-plastic final inner radius.

The first-order scheme dissipates kinetic energy numerically at a rate ~ rho a |grad v|^2 h (a includes the shear
wave speed), comparable to the plastic work on affordable meshes: the shell stops early, and the final inner radius
converges from above at about first order. Measured on the wedge (inner-radius error at h = 2 / 1.4 / 1 / 0.7 mm):
V0 = 417.1: +13.7 / +9.9 / +7.4 / +5.5 %; 454.7: +19.2 / +14.2 / +10.8 / +8.2 %; 490.2: +26.6 / +19.9 / +15.4 /
+11.9 %. So the check is on convergence: the scene runs on a thin wedge (geometry/shell_wedge2d.geo, 1/64 of the
circle: the flow is radial, and the quarter shell gives the same radii to 1e-4) at h = 1.4, 1 and 0.7 mm, with
--check (conservation; the scene's own radius tolerance is switched off), and
  - the shell has stopped: kinetic energy at t_f below 1e-3 of the initial one;
  - the inner-radius error decreases with h;
  - the fit r(h) = r_0 + C h^p through the three radii has an order 0.5 <= p <= 2 (measured 0.86 - 0.90) and its
    limit r_0 is within TOL = 3 % of the exact radius R_EXACT (5 / 4.5 / 4 cm for V0 = 417.1 / 454.7 / 490.2 m/s;
    measured +0.1 / +1.0 / +2.5 %; a first-order Richardson extrapolation from the two finest meshes, printed too,
    gives +0.9 / +2.1 / +3.6 %).
The converged GPR radius need not equal the rigid-perfectly-plastic one exactly: elasticity, compressibility and the
rate-dependent flow stress of the power law (tau10 = 1e-6 s, n = 20; see the scene) shift it by up to ~1 %.
Run time: about 70 / 90 / 100 s per velocity on one core.

usage: shell_collapse.py UNILAG SCENE WORKDIR R_EXACT
"""
import glob
import json
import os
import subprocess
import sys

import h5py
import numpy as np

SIZES = [0.0014, 0.001, 0.0007]
TOL = 0.03
WEDGE = "geometry/shell_wedge2d.geo"


def kinetic(path):
    with h5py.File(path, "r") as f:
        m = f["density"][:, 0] * f["volume"][:, 0]
        v = f["velocity"][...]
    return 0.5 * np.sum(m * np.sum(v * v, axis=1))


def main():
    unilag, scene, work, r_exact = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    name = os.path.splitext(os.path.basename(scene))[0]
    ok = True
    rows = []
    for h in SIZES:
        out = os.path.join(work, f"{name}_h{h}")
        subprocess.run([unilag, "run", scene, "--quiet", "--check", "--set", "exact.radius_tolerance=0", "--set",
                        f"mesh.geometry={WEDGE}", "--set", f"mesh.size={h}", "--set", "output.interval=0",
                        "--output", out], check=True)
        with open(f"{out}/summary.json") as f:
            s = json.load(f)
        r = s["boundary_mean_radius"]["inner"]
        dumps = sorted(glob.glob(f"{out}/unilag_*.h5"))
        ke = kinetic(dumps[-1]) / kinetic(dumps[0])
        rows.append((h, r))
        print(f"h={h:<7} cells={s['cells']:<5} t={s['t_final']:.3g} inner radius {r:.5f} m "
              f"(exact {r_exact}, error {(r - r_exact) / r_exact:+.2%}); final/initial kinetic energy {ke:.2e}")
        if not ke < 1e-3:
            print("FAIL: the shell has not stopped")
            ok = False
    errs = [abs(r - r_exact) for _, r in rows]
    if not all(b < a for a, b in zip(errs, errs[1:])):
        print("FAIL: the radius error does not decrease with h")
        ok = False
    (h1, r1), (h2, r2), (h3, r3) = rows
    print(f"first-order Richardson from the two finest meshes: {r3 + (r3 - r2) * h3 / (h2 - h3):.5f} m")
    # r = r0 + C h^p through the three points: (r1 - r2)/(r2 - r3) = (h1^p - h2^p)/(h2^p - h3^p), bisection on p
    q = (r1 - r2) / (r2 - r3) if r2 != r3 else float("inf")
    f = lambda p: (h1**p - h2**p) / (h2**p - h3**p) - q
    lo, hi = 0.05, 5.0
    if not (np.isfinite(q) and f(lo) * f(hi) < 0):
        print(f"FAIL: no power law r0 + C h^p through the three radii (ratio of differences {q:.3g})")
        ok = False
        p, r0 = float("nan"), float("nan")
    else:
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if f(lo) * f(mid) <= 0 else (mid, hi)
        p = 0.5 * (lo + hi)
        r0 = r3 - (r2 - r3) / (h2**p - h3**p) * h3**p
        err = (r0 - r_exact) / r_exact
        print(f"fit r0 + C h^p: order p = {p:.2f}, r0 = {r0:.5f} m, error {err:+.2%} (tolerance {TOL:.0%})")
        if not 0.5 <= p <= 2.0:
            print("FAIL: observed order outside [0.5, 2]: not in the asymptotic range")
            ok = False
        ok &= abs(err) <= TOL
    print("shell_collapse:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
