#!/usr/bin/env python3
"""2D Sedov on symmetry planes (docs/gpr-model.md 3.3, "Symmetry planes"): runs UNILAG on SCENE with the given
--set overrides and checks, from the first and last output and steps.csv, that
  - the nodes on the sides of the mesh's bounding box (the planes x = 0 and y = 0, and the walls there are) stay on
    them (|offset| <= 1e-12);
  - no cell is denser than MAX_DENSITY (the exact peak is 6);
  - the time step never falls below half the largest step taken before it (no collapse; the last step, which
    stops at the end time, aside).
Before the fix the planes' round-off kinks grew by about 100x per 0.05 in time: at 64k cells, order 1, the plane
nodes were 4e-4 off at t = 0.65, a cell reached density 19.6 and the step had fallen 8x since t = 0.61.

usage: sedov_symmetry.py UNILAG SCENE WORKDIR MAX_DENSITY [--set key=value ...]
"""
import glob
import subprocess
import sys

import h5py
import numpy as np


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    unilag, scene, work, max_density = sys.argv[1], sys.argv[2], sys.argv[3], float(sys.argv[4])
    subprocess.run([unilag, "run", scene, "--quiet", "--check", "--output", work] + sys.argv[5:], check=True)
    files = sorted(glob.glob(f"{work}/unilag_*.h5"))
    with h5py.File(files[0], "r") as f:
        x0 = f["coordinates"][:, :2]
    with h5py.File(files[-1], "r") as f:
        x1 = f["coordinates"][:, :2]
        rho = f["density"][:, 0]
    offset = 0.0
    for d in (0, 1):
        for side in (x0[:, d].min(), x0[:, d].max()):
            on = np.abs(x0[:, d] - side) < 1e-12
            offset = max(offset, np.abs(x1[on, d] - x0[on, d]).max())
    steps = np.genfromtxt(f"{work}/steps.csv", delimiter=",", names=True)
    dt = steps["dt"]
    drop = np.min(dt[1:-1] / np.maximum.accumulate(dt)[:-2])  # the last step only reaches the end time
    checks = [("largest offset of a side node from its side", offset, 1e-12),
              ("max density", rho.max(), max_density),
              ("largest fall of the step below the largest before it (1 / ratio)", 1.0 / drop, 2.0)]
    ok = True
    for what, value, bound in checks:
        good = value <= bound
        ok = ok and good
        print(f"{what}: {value:.4g} (bound {bound:g}) {'ok' if good else 'FAIL'}")
    print(f"{steps['step'][-1]:.0f} steps")
    print("sedov_symmetry:", "PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
