#!/usr/bin/env python3
"""The written specific internal energy is the one the EOS sees: for an ideal gas p = (gamma - 1) rho eps in every
cell of every dump, to round-off. (eps is E less the kinetic, elastic and thermal energies; writing E - |v|^2/2 fails
this wherever the gas carries elastic or thermal energy.)

usage: eos_consistency.py GAMMA DIR [DIR ...]
"""
import glob
import sys

import h5py
import numpy as np


def main():
    gamma = float(sys.argv[1])
    worst = 0.0
    for d in sys.argv[2:]:
        files = sorted(glob.glob(f"{d}/unilag_*.h5"))
        if not files:
            sys.exit(f"eos_consistency: no dumps in {d}")
        for name in files:
            with h5py.File(name, "r") as f:
                rho, p, eps = (f[k][:, 0] for k in ("density", "pressure", "specific_internal_energy"))
            err = np.abs(p - (gamma - 1.0) * rho * eps).max() / np.abs(p).max()
            worst = max(worst, err)
            print(f"{name}: max |p - (gamma - 1) rho eps| / max p = {err:.2e}")
    if not worst <= 1e-12:
        sys.exit(f"eos_consistency: FAIL, {worst:.2e} > 1e-12")
    print("eos_consistency: PASS")


if __name__ == "__main__":
    main()
