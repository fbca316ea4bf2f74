#!/usr/bin/env python3
"""Beryllium shell collapse (docs/gpr-model.md 3.6, inputs/be_shell2d*.yaml) against the rigid-plastic final inner
radius.

The scheme's numerical dissipation (at first order ~ rho a |grad v|^2 h, a including the shear wave speed) competes
with the plastic work and stops the shell early, so the final inner radius converges from above. At first order it
converges at order ~0.9 and is 5.5 / 8.2 / 11.9 % large at 0.7 mm for V0 = 417.1 / 454.7 / 490.2 m/s, so the scenes
run at second order (scheme.order: 2). The check: the scene runs on a thin wedge (geometry/shell_wedge2d.geo, 1/64
of the circle: the flow is radial, and the quarter shell gives the same radii to 1e-4) at h = 1 and 0.5 mm, with
--check (conservation; the scene's radius tolerance, too, at the finer mesh), and
  - the shell has stopped: kinetic energy at t_f below 1e-3 of the initial one;
  - the inner-radius error decreases with h, at an observed order of at least 1 (measured 2.2 / 1.8 / 1.5);
  - at h = 0.5 mm the inner radius is within TOL = 3 % of the exact one R_EXACT (5 / 4.5 / 4 cm; measured
    +0.48 / +1.1 / +2.05 %; at 1 mm +2.2 / +3.7 / +5.8 %).
The converged GPR radius need not equal the rigid-perfectly-plastic one exactly: elasticity, compressibility and the
rate-dependent flow stress of the power law (tau10 = 1e-6 s, n = 20; see the scene) shift it by up to ~1 %.
Run time: about 150 s per velocity on one core.

usage: shell_collapse.py UNILAG SCENE WORKDIR R_EXACT
"""
import glob
import json
import os
import subprocess
import sys

import h5py
import numpy as np

SIZES = [0.001, 0.0005]
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
        tol = [] if h == SIZES[-1] else ["--set", "exact.radius_tolerance=0"]
        subprocess.run([unilag, "run", scene, "--quiet", "--check"] + tol + ["--set", "scheme.order=2", "--set",
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
    (h1, r1), (h2, r2) = rows
    e1, e2 = (r1 - r_exact) / r_exact, (r2 - r_exact) / r_exact
    order = np.log(abs(e1) / abs(e2)) / np.log(h1 / h2) if e2 != 0 else float("inf")
    print(f"observed order {order:.2f}; error at h = {h2}: {e2:+.2%} (tolerance {TOL:.0%})")
    if not order >= 1.0:
        print("FAIL: observed order below 1")
        ok = False
    ok &= abs(e2) <= TOL
    print("shell_collapse:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
