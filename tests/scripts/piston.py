#!/usr/bin/env python3
"""A piston at speed U = 1 into a cold ideal gas (tests/scenes/piston_cold2d.yaml, gamma 5/3) against the exact
strong shock, from the run's last dump: at t = 0.5 the piston is at x = 0 and the shock at x = -0.5 + 4/3 * 0.5;
between them the density is 4 and the specific internal energy 1/2. Asserts the run completed, every field is
finite, the mean density and internal energy of the cells in the middle of the shocked layer within 3%, and the shock
(where the density crosses 2.5, furthest cell) within two cells of the exact position.

usage: piston.py RUN_DIR
"""
import glob
import json
import sys

import h5py
import numpy as np


def main():
    run = sys.argv[1]
    with open(f"{run}/summary.json") as f:
        s = json.load(f)
    fails = []
    if s["status"] != "completed":
        fails.append(f"status {s['status']}")
    dump = sorted(glob.glob(f"{run}/unilag_*.h5"))[-1]
    with h5py.File(dump, "r") as f:
        x, c = f["coordinates"][:], f["connectivity"][:]
        rho = f["density"][:].ravel()
        eps = f["specific_internal_energy"][:].ravel()
        if not all(np.all(np.isfinite(f[k][:])) for k in f):
            fails.append("a field is not finite")
    cx = x[c][:, :, 0].mean(axis=1)
    t, shock = s["t_final"], -0.5 + 4.0 / 3.0 * s["t_final"]
    layer = (cx > 0.2 * shock) & (cx < 0.8 * shock)
    rho_mean, eps_mean = rho[layer].mean(), eps[layer].mean()
    front = cx[rho > 2.5].max()
    print(f"t {t}: shocked layer rho {rho_mean:.4f} (exact 4), eps {eps_mean:.4f} (0.5), "
          f"shock at {front:.4f} (exact {shock:.4f})")
    if abs(rho_mean - 4.0) > 0.12 or abs(eps_mean - 0.5) > 0.015:
        fails.append("the shocked state is off")
    if abs(front - shock) > 0.01:
        fails.append("the shock is misplaced")
    for f in fails:
        print("piston: FAIL, " + f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
